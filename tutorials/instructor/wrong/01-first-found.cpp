// Tutorial 01, a wrong answer: the first object hit in id order, not the nearest.
// BEGIN ANSWER
    // Convexity: a ray leaving a surface cannot meet it again
    if (id == q.origin.object && !q.origin.inside) return;
    ++n.intersectionTests;
    const double t = scene.intersect(q.ray, id, q.origin);
    if (t < q.tmax && best.object < 0) best = {id, t};
// END ANSWER
// KEEP SOLUTION
