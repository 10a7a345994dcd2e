#pragma once
/// \file
/// \brief The ray tree of one pixel, as rows: every ray the pixel traced, under the ray that
/// spawned it ("the links represent rays of light and the nodes represent the surfaces that
/// those rays intersected"), with its cache decision. The Qt window's Ray tree panel and the
/// page's ray tree list show these rows. RayCache's own addition.
#include <cstdint>
#include <string>
#include <vector>

#include "view/session_state.h"

namespace rc {

/// One ray of a pixel's ray tree.
struct RayTreeRow {
    int event = -1;   ///< its index in the recorder's events
    int parent = -1;  ///< the row of the ray that spawned it, -1 for the eye ray's
    int depth = 0;    ///< rows above it in the tree (0: the eye ray)
    std::string path;      ///< e.g. "eye/reflection"
    std::string kind;      ///< eye, shadow, reflection or refraction
    std::string hit;       ///< objectLabel(), or "?" for a deferred attempt
    std::string decision;  ///< decisionText()
    std::int64_t tests = 0;
    std::int64_t step = 0;
    bool deferred = false;  ///< an attempt put off to a later pass (it is answered again)
    bool miss = false;      ///< a committed cache miss
};

/// The rays of `pixel`, oldest first: each after its parent; a deferred attempt has no
/// children (the ray's answer, later, has them).
std::vector<RayTreeRow> rayTreeRows(const SessionState& s, int pixel);

}  // namespace rc
