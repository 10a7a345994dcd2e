// Tutorial 03, a wrong answer the check must reject: every sphere is a potential blocker (distance -1): correct, useless
// BEGIN ANSWER
    nested_ = false;  // the hull keeps its two spheres; distance() needs nothing else
// END ANSWER
// BEGIN ANSWER
    return -1.0 + 0.0 * glm::length(p - a_.c - b_.c);
// END ANSWER
