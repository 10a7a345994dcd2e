#include "search/list_arena.h"

#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace rc {

namespace {
constexpr std::size_t kHugePage = std::size_t(2) << 20;

void* allocateBlock(std::size_t size) {
    // Aligned to a huge page so that the system can back it by whole huge pages
    void* p = std::aligned_alloc(kHugePage, size);
    if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    madvise(p, size, MADV_HUGEPAGE);  // a request only: refused, the block is ordinary memory
#endif
    return p;
}
}  // namespace

ListArena::~ListArena() {
    for (Block& b : blocks_) std::free(b.data);
}

void* ListArena::raw(std::size_t bytes) {
    bytes = (bytes + kAlign - 1) / kAlign * kAlign;
    // The block being filled, else the next one that has room (after a rewind), else a new one
    while (current_ < blocks_.size() && blocks_[current_].used + bytes > blocks_[current_].size) {
        if (current_ + 1 < blocks_.size()) blocks_[current_ + 1].used = 0;
        else break;
        ++current_;
    }
    if (current_ >= blocks_.size() || blocks_[current_].used + bytes > blocks_[current_].size) {
        const std::size_t size = (std::max(bytes, kBlockBytes) + kHugePage - 1) / kHugePage * kHugePage;
        blocks_.push_back({allocateBlock(size), size, 0});
        current_ = blocks_.size() - 1;
    }
    Block& b = blocks_[current_];
    void* p = static_cast<char*>(b.data) + b.used;
    b.used += bytes;
    return p;
}

void ListArena::rewind(const Mark& m) {
    if (m.block >= blocks_.size()) return;  // nothing was taken
    current_ = m.block;
    blocks_[current_].used = m.used;
}

std::size_t ListArena::bytes() const {
    std::size_t total = 0;
    for (const Block& b : blocks_) total += b.size;
    return total;
}

}  // namespace rc
