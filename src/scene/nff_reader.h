#pragma once
/// \file
/// \brief Reader for Eric Haines' Neutral File Format (NFF), as the SPD scenes use it.
///
/// The reader works on tokens, not lines: a `v` block or a polygon may be spread over
/// several lines, and several keywords may share one line. A `#` that starts a token
/// starts a comment that runs to the end of the line.
///
/// Supported keywords:
/// - `v` then `from x y z`, `at x y z`, `up x y z`, `angle a` (full field of view in
///   degrees), `hither h`, `resolution w h`, in any order (`hither` may be left out);
/// - `b r g b` (background; may come before `v`);
/// - `l x y z [r g b]` (point light; the colour is optional);
/// - `f r g b Kd Ks Shine T ior` (the material of every primitive that follows; SPD
///   writes ior 0 for opaque materials, so ior is read only where T > 0);
/// - `s x y z r` (sphere);
/// - `c bx by bz br ax ay az ar` (an open truncated cone between two disc centres; equal
///   radii make a cylinder);
/// - `p N` then N vertices, `pp N` then N (vertex, normal) pairs (simple planar polygons,
///   convex or concave).
///
/// A primitive that comes before any `f` gets a white diffuse material. Everything
/// else (`tpp`, `tp`, ...) is rejected. A polygon of zero area (collinear or coincident
/// vertices, as SPD's coarse teapot writes at its poles) is skipped, not refused: no ray
/// can hit it. Each one is named in Scene::skipped as `file:line:column: message` (the
/// `p` or `pp` keyword) and counted in Scene::skippedCount. A UTF-8 byte-order mark at
/// the start of the file is skipped too; columns count from the byte after it, as they do
/// in the page, whose text decoder drops it. Every error is an rc::SceneError whose what()
/// is `file:line:column: message`; lines and columns count from 1, columns in bytes.
/// An error "at end of file" points just past the file's last token (1:1 in an empty
/// file). No input can make the reader crash, hang or allocate more than a small
/// multiple of the input's size.
#include <cstddef>
#include <string>
#include <string_view>

#include "scene/scene.h"

namespace rc {

/// The reader's hard limits: anything beyond them is rejected as an error, before
/// any memory is allocated for it.
struct NffLimits {
    /// Most primitives (spheres, cones and polygons) in one scene.
    static constexpr long maxPrimitives = 10'000'000;
    /// Most vertices in one `p` or `pp` polygon.
    static constexpr long maxPolygonVertices = 10'000;
    /// Largest image width or height in `resolution`.
    static constexpr long maxResolution = 16384;
    /// Largest magnitude of any number (so that squares of coordinates stay finite).
    static constexpr double maxMagnitude = 1e100;
    /// Most skipped polygons named in Scene::skipped (the rest are only counted).
    static constexpr std::size_t maxSkippedNamed = 100;
    /// Largest input, in bytes (1 GiB).
    static constexpr std::size_t maxFileBytes = std::size_t(1) << 30;
};

/// Parses NFF `text`; `fileName` names it in errors and gives Scene::name its stem.
/// `maxPrimitives` exists so that tests can exercise the limit cheaply.
/// \throws SceneError on anything malformed or unsupported.
Scene parseNff(std::string_view text, const std::string& fileName,
               long maxPrimitives = NffLimits::maxPrimitives);

/// Reads and parses the NFF file at `path`.
/// \throws SceneError; a file that cannot be read is reported at line 0, column 0.
Scene readNffFile(const std::string& path);

}  // namespace rc
