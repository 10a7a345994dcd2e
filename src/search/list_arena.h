#pragma once
/// \file
/// \brief RayCache's own bookkeeping: the memory a cache's lists are kept in all render
/// long, taken in large blocks rather than two small allocations per list.
///
/// A cache that builds thousands of lists touches megabytes of fresh memory, a page at a
/// time; on a virtual machine each first touch of a page is a fault that costs microseconds
/// (`perf stat -e page-faults` counts them against the uncached render's). The arena takes blocks of 4 MiB aligned to 2 MiB and, on
/// Linux, asks for them to be backed by huge pages (madvise), so a block costs a few
/// faults; where the system refuses, it is ordinary memory. What is kept there is the same
/// either way: the answers do not depend on it.
#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace rc {

/// Blocks of memory handed out in pieces, given back only all at once past a mark.
class ListArena {
public:
    /// Where the arena stood: everything taken after it can be given back (rewind()).
    struct Mark {
        std::size_t block = 0, used = 0;
    };
    ListArena() = default;
    ListArena(const ListArena&) = delete;
    ListArena& operator=(const ListArena&) = delete;
    ~ListArena();
    /// Room for `count` values of T (aligned to 8 bytes), kept until rewound past or the
    /// arena is destroyed; its contents are not set.
    template <typename T>
    T* take(std::size_t count) {
        static_assert(alignof(T) <= kAlign);
        return static_cast<T*>(raw(count * sizeof(T)));
    }
    Mark mark() const { return {current_, blocks_.empty() ? 0 : blocks_[current_].used}; }
    /// Gives back everything taken since `m` (the blocks are kept for reuse).
    void rewind(const Mark& m);
    /// Bytes of the blocks held.
    std::size_t bytes() const;
    static constexpr std::size_t kBlockBytes = std::size_t(4) << 20;

private:
    static constexpr std::size_t kAlign = 8;
    struct Block {
        void* data = nullptr;
        std::size_t size = 0, used = 0;
    };
    void* raw(std::size_t bytes);
    std::vector<Block> blocks_;
    std::size_t current_ = 0;  ///< the block being filled
};

}  // namespace rc
