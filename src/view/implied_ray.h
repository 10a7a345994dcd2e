#pragma once
/// \file
/// \brief The ray a pixel traces at one ray-tree path, traced again: what the recorder's
/// log need not keep of every event.
#include <optional>

#include "render/render_session.h"

namespace rc {

/// Can the rays of `session`'s render be traced again exactly, from the pixel and the path
/// alone? A ray's origin and direction are a pure function of the scene, the options and
/// the answers of the rays above it on its path (eye, reflection and refraction rays,
/// whose answers are the nearest hit whatever the cache), so they can, unless the render's
/// complete search is Embree's: its single-precision nearest hit may differ from the answer
/// a cache gives in double precision, and the rays below it with it.
bool raysImplied(const rc::RenderSession& session);

/// A ray traced again, and its nearest hit.
struct ImpliedRay {
    rc::RayTask task;
    rc::Answer nearest;  ///< the render's complete search's answer
};

/// The task (query, key, sample) that `session`'s render traces for `pixel` at ray-tree
/// path `node`, made again: the eye ray of the path's pixel sample, then down the path,
/// each ray answered by the render's complete search and shaded for its children (as
/// SampleFan does for the whole tree). Nothing when the pixel's rays at the path were
/// never made (a node the tree does not have, or a child its parent's answer does not
/// spawn). Its nearest hit is every answer's but a shadow ray's, which a cache may answer
/// with any object in the way.
std::optional<ImpliedRay> impliedRay(const rc::RenderSession& session, int pixel, int node);

}  // namespace rc
