// Tutorial 03, a wrong answer: a capsule of the larger radius around the two centres. It holds
// the hull, so its lists hold every blocker, but it is not the hull: outside it the distance is
// less than the exact one, and cube:4's lists are longer than the oracle's
// BEGIN ANSWER
    nested_ = false;  // the hull keeps its two spheres; distance() needs nothing else
// END ANSWER
// BEGIN ANSWER
    const Vec3 ab = b_.c - a_.c;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a_.c, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a_.c + t * ab)) - std::max(a_.r, b_.r);
// END ANSWER
