#include "view/step_checkpoints.h"

#include <bit>
#include <cstdio>
#include <unordered_set>

namespace rc {

namespace {
/// Is the checkpoint at spacing `m` still wanted when the newest is at spacing `newest`?
bool wanted(std::int64_t m, std::int64_t newest) {
    // [checkpoint-spacing]
    // Of the checkpoints d spacings back, every 2^(floor(log2 d) - 1)-th stays: two per
    // doubling of the distance, and step 0 always
    const std::int64_t d = newest - m;
    if (m == 0 || d < 4) return true;
    const int level = std::bit_width(std::uint64_t(d)) - 2;
    return m % (std::int64_t(1) << level) == 0;
    // [checkpoint-spacing]
}
}  // namespace

StepCheckpoint StepCheckpoints::spare() {
    if (spares_.empty()) return StepCheckpoint();
    StepCheckpoint c = std::move(spares_.back());
    spares_.pop_back();
    return c;
}

void StepCheckpoints::add(StepCheckpoint c) {
    next_ = c.steps() + every_;
    const std::int64_t newest = c.steps() / every_;
    list_.push_back(std::move(c));
    std::vector<StepCheckpoint> kept;
    kept.reserve(list_.size());
    for (StepCheckpoint& k : list_) {
        if (wanted(k.steps() / every_, newest)) kept.push_back(std::move(k));
        else if (spares_.empty()) spares_.push_back(std::move(k));
    }
    list_ = std::move(kept);
}

const StepCheckpoint* StepCheckpoints::backTo(std::int64_t step) {
    std::size_t keep = 0;
    while (keep < list_.size() && list_[keep].steps() <= step) ++keep;
    if (keep == 0) return nullptr;
    if (keep < list_.size() && spares_.empty()) spares_.push_back(std::move(list_[keep]));
    list_.erase(list_.begin() + std::ptrdiff_t(keep), list_.end());
    next_ = list_.back().steps() + every_;
    return &list_.back();
}

std::vector<std::int64_t> StepCheckpoints::steps() const {
    std::vector<std::int64_t> out;
    for (const StepCheckpoint& c : list_) out.push_back(c.steps());
    return out;
}

std::size_t StepCheckpoints::bytes() const {
    std::size_t b = 0;
    std::unordered_set<const void*> rows;
    for (const StepCheckpoint& c : list_) {
        b += c.session.bytes() - c.session.image.ownBytes() + c.recorder.bytes();
        for (const auto& row : c.session.image.rows())
            if (rows.insert(row.get()).second) b += row->size() * sizeof(std::int64_t);
    }
    return b;
}

std::string StepCheckpoints::summary() const {
    char text[128];
    std::snprintf(text, sizeof text, "%zu checkpoints (every %lld steps), %.1f MB", list_.size(), (long long)every_,
                  double(bytes()) / (1024.0 * 1024.0));
    return text;
}

}  // namespace rc
