// Tutorial 02, a wrong answer the check must reject: the radius is the distance to the nearest centre (r_j forgotten)
// BEGIN ANSWER
    const rc::Vec3 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    // The nearest point is a + t (b - a), with t clamped to the segment
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
// END ANSWER
// BEGIN ANSWER
    // The gap to the nearest other sphere: its centre's distance to the segment minus its radius
    double radius = rc::kNoHit;
    for (int j = 0; j < int(spheres.size()); ++j)
        if (j != hit) radius = std::min(radius, segmentDistance(spheres[j].c, a, b));
    return radius;
// END ANSWER
// BEGIN ANSWER
    // The capsule is convex: both endpoints inside put the whole segment inside
    return segmentDistance(p, a, b) <= radius && segmentDistance(q, a, b) <= radius;
// END ANSWER
