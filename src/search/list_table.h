#pragma once
/// \file
/// \brief The index of a log of lists: which list, by number, a key has.
///
/// Kept over std::unordered_map: faster finds and inserts, as raycache_microbench "[containers]" measures side by side.
#include <cstdint>
#include <vector>

namespace rc {

/// An open-addressed table from 64-bit keys to the numbers of lists kept in a log (a
/// deque that only grows, or is cut back at a checkpoint). A lookup per ray: no node to
/// follow, one multiply to hash, and the table at most half full. A slot holds its key and
/// its number side by side: a find reads one cache line, not one in each of two arrays.
class ListTable {
public:
    static constexpr std::uint32_t kNone = std::uint32_t(-1);
    /// The number kept for `key`, or kNone.
    std::uint32_t find(std::uint64_t key) const {
        if (slots_.empty()) return kNone;
        const Slot& s = slots_[slot(key)];
        return s.key == 0 ? kNone : s.number;
    }
    /// Keeps `number` for `key` (a key not kept yet).
    void insert(std::uint64_t key, std::uint32_t number);
    /// Forgets every key whose number is `n` or more.
    void keepBelow(std::uint32_t n);

private:
    std::size_t slot(std::uint64_t key) const {
        // Fibonacci hashing into a power-of-two table, then the next free or matching slot
        const std::size_t mask = slots_.size() - 1;
        std::size_t k = std::size_t((key * 0x9E3779B97F4A7C15ull) >> 20) & mask;
        while (slots_[k].key != 0 && slots_[k].key != key + 1) k = (k + 1) & mask;
        return k;
    }
    struct Slot {
        std::uint64_t key = 0;  ///< key + 1 (0: empty)
        std::uint32_t number = 0;
    };
    /// Puts every key of `old` whose number is below `n` into an empty table of `size` slots.
    void refill(const std::vector<Slot>& old, std::size_t size, std::uint32_t n);
    std::vector<Slot> slots_;
    std::size_t count_ = 0;  ///< keys kept
};

}  // namespace rc
