#pragma once
/// \file
/// \brief A ray: an origin and a unit direction.
#include <glm/vec3.hpp>

/// The Qt-free core of RayCache: geometry, scenes, the complete search and the caches,
/// the tracer, the orders and the analysis (see the pages of this site, one per idea).
namespace rc {

using Vec3 = glm::dvec3;

/// A ray `o + t d`. Every routine in RayCache assumes `d` has unit length.
struct Ray {
    Vec3 o{0.0};  ///< origin
    Vec3 d{0.0, 0.0, 1.0};  ///< unit direction

    /// The point at parameter `t`.
    Vec3 at(double t) const { return o + t * d; }
};

}  // namespace rc
