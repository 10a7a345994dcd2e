#pragma once
/// \file
/// \brief A complete search that answers from a table: the answers another search gave,
/// replayed in the order they were asked. (How `raycache bench` measures what a render
/// costs apart from searching.)
#include <cstddef>
#include <memory>
#include <vector>

#include "search/complete_search.h"

namespace rc {

/// The answers of a render, in the order its searches were made.
using AnswerTable = std::vector<Answer>;

/// Searches with `inner` and writes every answer to `table`.
class RecordingSearch final : public CompleteSearch {
public:
    RecordingSearch(const Scene& scene, std::unique_ptr<CompleteSearch> inner, AnswerTable& table)
        : CompleteSearch(scene), inner_(std::move(inner)), table_(table) {}
    Answer nearest(const Query& q, Counters& n) const override {
        const Answer a = inner_->nearest(q, n);
        table_.push_back(a);
        return a;
    }
    std::string name() const override { return "recording " + inner_->name(); }
    bool cheap() const override { return inner_->cheap(); }

private:
    std::unique_ptr<CompleteSearch> inner_;
    AnswerTable& table_;
};

/// Gives back the answers of `table`, one per search, testing nothing. A render with the
/// same scene, options and no cache asks the same questions in the same order, so its
/// time is everything a render does but search: making rays, stepping the order,
/// shading, adding to pixels, counting.
class TableSearch final : public CompleteSearch {
public:
    TableSearch(const Scene& scene, const AnswerTable& table) : CompleteSearch(scene), table_(table) {}
    Answer nearest(const Query&, Counters&) const override {
        const std::size_t i = next_++;
        return i < table_.size() ? table_[i] : Answer{};
    }
    std::string name() const override { return "table"; }
    bool cheap() const override { return false; }
    /// Searches asked for so far (the table's size when the render asked the same questions).
    std::size_t asked() const { return next_; }

private:
    const AnswerTable& table_;
    mutable std::size_t next_ = 0;
};

}  // namespace rc
