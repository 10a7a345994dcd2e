#pragma once
/// \file
/// \brief Objects ordered by their reach without comparing them: a radix sort of doubles.
#include <cstdint>
#include <cstring>
#include <vector>

namespace rc {

/// Orders (reach, id) pairs as std::sort orders them (by reach, ties by the lower id), given
/// pairs whose ids ascend, by a least-significant-digit radix sort of the reaches' bits: a
/// pass per byte that differs between them, each a count and a move, with no comparison
/// for the processor to guess. (A site's order sorts every object by its reach: with
/// std::sort, one comparison in three was a mispredicted branch.) `scratch` is reused.
class ReachOrder {
public:
    struct Entry {
        std::uint64_t key;  ///< the reach's bits, flipped so that unsigned order is numeric order
        std::uint32_t id;
    };
    /// Appends a pair; ids must come in ascending order.
    void push(double reach, std::uint32_t id) {
        // -0.0 and 0.0 are equal reaches: one key for both (x + 0.0 is +0.0 for either)
        // (memcpy, not std::bit_cast: the web edition's library has none)
        const double value = reach + 0.0;
        std::uint64_t bits;
        std::memcpy(&bits, &value, sizeof bits);
        entries_.push_back({bits >> 63 ? ~bits : bits | (std::uint64_t(1) << 63), id});
    }
    void clear() { entries_.clear(); }
    /// Sorts; the pairs are then entries() in order.
    void sort() {
        const std::size_t n = entries_.size();
        if (n < 2) return;
        scratch_.resize(n);
        for (int shift = 0; shift < 64; shift += 8) {
            std::uint32_t count[256] = {};
            for (const Entry& e : entries_) ++count[(e.key >> shift) & 0xFF];
            // Every key has this byte in common: nothing to move
            if (count[(entries_[0].key >> shift) & 0xFF] == n) continue;
            std::uint32_t at = 0;
            for (std::uint32_t& c : count) {
                const std::uint32_t here = c;
                c = at;
                at += here;
            }
            // Stable: equal keys keep their order, the ids' ascending one
            for (const Entry& e : entries_) scratch_[count[(e.key >> shift) & 0xFF]++] = e;
            entries_.swap(scratch_);
        }
    }
    const std::vector<Entry>& entries() const { return entries_; }

private:
    std::vector<Entry> entries_, scratch_;
};

}  // namespace rc
