#pragma once
/// \file
/// \brief The built-in `balls:N`: Eric Haines' SPD "balls" database (the sphereflake),
/// as SPD's `balls -s N -c -r 0` prints it.
#include "scene/scene.h"

namespace rc {

/// Largest size of `balls:N`: size 6 holds 597,871 spheres (about 50 MB of scene before
/// any acceleration structure); size 7 would hold 5,380,840.
constexpr int kMaxSphereflake = 6;

/// Number of spheres of the sphereflake of size `size`: 1 + 9 + ... + 9^size
/// (size 4, SPD's default, has 7,381).
long sphereflakeSpheres(int size);

/// SPD's "balls" database of size `size` (1 <= size <= kMaxSphereflake): a sphere of
/// radius 0.5 at the origin, each sphere carrying 9 children of a third of its radius
/// that touch it (six around its equator, three above, relative to the direction from
/// its parent), recursively `size` levels deep; a 24 x 24 ground square at z = -0.5,
/// three lights, SPD's view, background and two materials.
///
/// The scene is the one the NFF reader makes of SPD's output, bit for bit: every sphere
/// is computed with SPD's own sequence of double-precision operations (which matters
/// where a child points straight down and the rotation's axis is made of rounding
/// noise), then every number is rounded to the six significant digits that SPD prints
/// (C's `g` format). Spheres come in SPD's order (depth first). Scene::name is `balls:N`
/// for size N.
/// \throws SceneError(`balls:N`, 0, 0, message) for a size N out of range.
Scene makeSphereflake(int size);

}  // namespace rc
