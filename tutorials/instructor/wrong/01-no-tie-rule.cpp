// Tutorial 01, a wrong answer: the nearest hit, but a tie kept by whichever object came first (right only when objects are tested in id order).
// BEGIN ANSWER
    // Convexity: a ray leaving a surface cannot meet it again
    if (id == q.origin.object && !q.origin.inside) return;
    ++n.intersectionTests;
    const double t = scene.intersect(q.ray, id, q.origin);
    if (t < q.tmax && t < best.t) best = {id, t};
// END ANSWER
// KEEP SOLUTION
