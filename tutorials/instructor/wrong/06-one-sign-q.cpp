// Tutorial 06, a wrong answer the check must reject: stableQuadraticRoots with q = -h + sqrt(disc)
// whatever the sign of h (sphereRootsStable as the reference has it, so its roots come from here)
// BEGIN ANSWER
    const double q = -h + std::sqrt(disc);  // the sign of -h forgotten
    return {q / a, (q != 0.0) ? c / q : 0.0};
// END ANSWER
// KEEP SOLUTION
