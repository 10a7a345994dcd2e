#pragma once
/// \file
/// \brief Recording the answers of an uncached render, to replay them from a table
/// (rc::TableSearch): how `bench` and `table1` measure what a render costs besides searching.
#include <memory>

#include "render/render_session.h"
#include "search/accelerator.h"
#include "search/answer_table.h"

namespace rc {

/// The answers an uncached render of `o` (its search, its order) gets, in the order it asks.
/// `sink`, if given, hears that render's rays.
inline AnswerTable recordAnswers(const std::shared_ptr<const Scene>& scene, RenderOptions o,
                                 TraceSink* sink = nullptr) {
    AnswerTable table;
    o.cache = CacheKind::None;
    RenderSession session(scene, o, std::make_unique<RecordingSearch>(*scene, makeCompleteSearch(o.accel, *scene), table));
    if (sink) session.addSink(sink);
    session.run();
    return table;
}

}  // namespace rc
