#pragma once
/// \file
/// \brief The per-pixel overlays of a render (miss markers by reason, the breadth-first
/// regions), the caption of the ray in focus, and a ray chosen by its pixel and path:
/// what every viewer shows beside rc::focusShapes, made once here.
#include <cstdint>
#include <string>
#include <vector>

#include "view/path_index.h"
#include "view/ray_focus.h"

namespace rc {

/// The miss mark of one pixel: the reason (rc::MissReason's number) of its committed
/// cache miss at the index's path; 0 where its ray there was no miss or is not traced yet.
inline std::uint8_t missMark(const PathIndex& index, int pixel) {
    const PathIndex::Entry& e = index.at(pixel);
    return e.event >= 0 && Decision(e.decision) == Decision::Miss ? e.reason : 0;
}
/// missMark() of every pixel of `index`, rows top to bottom.
std::vector<std::uint8_t> missLayer(const PathIndex& index);
/// The same at ray-tree path `path` of `s`, reading its whole event log.
std::vector<std::uint8_t> missLayer(const SessionState& s, int path);

/// What a pixel shows of the breadth-first fill at the path being filled.
enum class RegionMark : std::uint8_t { None = 0, Current = 1, Edge = 2 };
/// For each pixel of a `width` x `height` image whose events at the path being filled
/// `index` holds, a RegionMark: in region `current` (the one being filled), on the edge of
/// a finished region (its right or lower neighbour lies in another), or neither.
std::vector<std::uint8_t> regionLayer(const PathIndex& index, int width, int height, int current);
/// The same for `s`, reading its whole event log; all None when the order has no frontier.
std::vector<std::uint8_t> regionLayer(const SessionState& s);

/// The caption of a render: its scene, cache, order, size and step, then the ray in focus
/// (pixel, path, what it hit, the cache's decision, its tests), or the selected pixel
/// not traced yet.
std::vector<std::string> focusCaption(const SessionState& s, const Selection& sel);

/// What caused the miss of the ray in focus, in words (empty when it is not a miss whose
/// entry is known).
std::string missCauseText(const SessionState& s, const RayFocus& f);

/// The recorded event of pixel `pixel` at path `path` (a cache-tree label such as
/// "eye/reflection", compared without spaces and case), preferring a committed one;
/// -1 with `error` saying which paths the pixel has.
int eventAtPath(const SessionState& s, int pixel, const std::string& path, std::string& error);

/// A ray worth showing when none is chosen (the paper's Figure 2 on screen): the newest
/// committed reflection ray that hit an object with potential blockers listed between the
/// two; else such an eye ray; failing that, the newest hit (any hit without blocker
/// lists). Its recorded event, -1 when nothing was hit yet.
int showcaseEvent(const SessionState& s);

}  // namespace rc
