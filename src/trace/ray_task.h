#pragma once
/// \file
/// \brief A ray waiting to be traced: a link of some pixel's ray tree.
#include "search/query.h"

namespace rc {

/// One ray of one pixel's ray tree. Whitted shading is linear, so the ray carries its
/// weight (the product of Ks and Kt along its path) and adds what it finds straight into
/// its pixel: no recursion, so rays can be traced in any order.
struct RayTask {
    Query query;
    int pixel = 0;    ///< y * width + x
    int node = 0;     ///< its path in the cache tree
    int depth = 1;    ///< the eye ray is depth 1
    Vec3 weight{1.0};  ///< what this ray finds is multiplied by this
    /// Shadow rays: the light this pixel receives if nothing is in the way (weighted).
    Vec3 unblocked{0.0};
};

}  // namespace rc
