// Tutorial 03, a wrong answer: the cone without its two spherical caps. It holds the hull, so
// its lists hold every blocker, but it is not the hull: beyond the spheres the distance is less
// than the exact one, and cube:4's lists are longer than the oracle's.
// BEGIN PREAMBLE

// The hull of spheres a and b, the distance to it; Hull::distance() calls it
static double hullDistanceOf(const rc::Vec3& p, const rc::Sphere& a, const rc::Sphere& b) {
    const rc::Vec3 axis = b.c - a.c;
    const double D = glm::length(axis);
    // Nested spheres: the hull is the larger one
    if (D <= std::abs(a.r - b.r)) {
        const rc::Sphere& big = a.r >= b.r ? a : b;
        return glm::length(p - big.c) - big.r;
    }
    // 2D coordinates: x along the axis from a, y >= 0 away from it
    const rc::Vec3 u = axis / D;
    const double x = glm::dot(p - a.c, u);
    const double y = glm::length(p - a.c - x * u);
    // Unit normal of the tangent line, n = (sin, cos) of the cone's half-angle
    const double s = (a.r - b.r) / D;
    const double c = std::sqrt(1.0 - s * s);
    // Project p on the tangent segment from a + ra n to b + rb n (its length is D c)
    const double along = (x - a.r * s) * c - (y - a.r * c) * s;
    (void)along;
    return x * s + y * c - a.r;                              // nearest to the cone
}
// END PREAMBLE
// BEGIN ANSWER
    nested_ = false;  // the hull keeps its two spheres; distance() needs nothing else
// END ANSWER
// BEGIN ANSWER
    return hullDistanceOf(p, a_, b_);
// END ANSWER
