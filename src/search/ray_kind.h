#pragma once
/// \file
/// \brief The kind of a ray (eye, shadow, reflection, refraction): a link of the ray tree.
///
/// A tracing idea, kept in the search layer because the searches need it: a query says
/// what kind of ray asks (the blocker cache answers shadow rays from the hull of origin and
/// light), the cache tree keys its paths by kind, and the counters count rays by kind.
#include <cstdint>
#include <string_view>

namespace rc {

/// The kind of a ray, i.e. of a link in the ray tree.
enum class RayKind : std::uint8_t { Primary, Shadow, Reflection, Refraction };
inline constexpr int kRayKinds = 4;
std::string_view toString(RayKind k);

}  // namespace rc
