// Tutorial 03, a wrong answer the check must reject: the sphere around both spheres instead of their hull: correct, far too many blockers
// BEGIN ANSWER
    nested_ = false;  // the hull keeps its two spheres; distance() needs nothing else
// END ANSWER
// BEGIN ANSWER
    const Vec3 mid = 0.5 * (a_.c + b_.c);
    return glm::length(p - mid) - (0.5 * glm::length(b_.c - a_.c) + std::max(a_.r, b_.r));
// END ANSWER
