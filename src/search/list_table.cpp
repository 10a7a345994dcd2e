#include "search/list_table.h"

#include <algorithm>
#include <utility>

namespace rc {

void ListTable::refill(const std::vector<Slot>& old, std::size_t size, std::uint32_t n) {
    slots_.assign(size, Slot{});
    count_ = 0;
    for (const Slot& s : old) {
        if (s.key == 0 || s.number >= n) continue;
        slots_[slot(s.key - 1)] = s;
        ++count_;
    }
}

void ListTable::insert(std::uint64_t key, std::uint32_t number) {
    // Keep the table at most half full
    if (2 * (count_ + 1) > slots_.size()) {
        const std::vector<Slot> old = std::move(slots_);
        refill(old, std::max<std::size_t>(64, 2 * old.size()), kNone);
    }
    slots_[slot(key)] = {key + 1, number};
    ++count_;
}

void ListTable::keepBelow(std::uint32_t n) {
    // Open addressing cannot erase in place: the keys kept go back into an empty table
    const std::vector<Slot> old = std::move(slots_);
    refill(old, old.size(), n);
}

}  // namespace rc
