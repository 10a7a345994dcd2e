#include "search/list_table.h"

#include <algorithm>
#include <utility>

namespace rc {

void ListTable::refill(const std::vector<std::uint64_t>& keys, const std::vector<std::uint32_t>& numbers,
                       std::size_t size, std::uint32_t n) {
    keys_.assign(size, 0);
    numbers_.assign(size, 0);
    count_ = 0;
    for (std::size_t k = 0; k < keys.size(); ++k) {
        if (keys[k] == 0 || numbers[k] >= n) continue;
        const std::size_t to = slot(keys[k] - 1);
        keys_[to] = keys[k];
        numbers_[to] = numbers[k];
        ++count_;
    }
}

void ListTable::insert(std::uint64_t key, std::uint32_t number) {
    // Keep the table at most half full
    if (2 * (count_ + 1) > keys_.size()) {
        const std::vector<std::uint64_t> keys = std::move(keys_);
        const std::vector<std::uint32_t> numbers = std::move(numbers_);
        refill(keys, numbers, std::max<std::size_t>(64, 2 * keys.size()), kNone);
    }
    const std::size_t k = slot(key);
    keys_[k] = key + 1;
    numbers_[k] = number;
    ++count_;
}

void ListTable::keepBelow(std::uint32_t n) {
    // Open addressing cannot erase in place: the keys kept go back into an empty table
    const std::vector<std::uint64_t> keys = std::move(keys_);
    const std::vector<std::uint32_t> numbers = std::move(numbers_);
    refill(keys, numbers, keys.size(), n);
}

}  // namespace rc
