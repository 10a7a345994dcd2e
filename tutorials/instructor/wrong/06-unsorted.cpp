// Tutorial 06, a wrong answer the check must reject: no swap: t0 > t1 when the origin is past the centre
// KEEP SOLUTION
// BEGIN ANSWER
    const rc::Vec3 f = ray.o - s.c;
    const double b = glm::dot(f, ray.d);
    // r^2 - |l|^2 with l the centre's perpendicular offset: no large squares cancel
    const rc::Vec3 l = f - b * ray.d;
    const double disc = s.r * s.r - glm::dot(l, l);
    if (disc < 0.0) return {};
    // q = -b - sign(b) sqrt(disc) adds two numbers of the same sign
    const double q = b > 0.0 ? -b - std::sqrt(disc) : -b + std::sqrt(disc);
    const double c = glm::dot(f, f) - s.r * s.r;
    double t0 = q != 0.0 ? c / q : 0.0, t1 = q;  // Vieta: t0 t1 = c
    return {true, t0, t1};
// END ANSWER
