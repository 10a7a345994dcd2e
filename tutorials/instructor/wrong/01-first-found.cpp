// Tutorial 01, a wrong answer: the first object hit in id order, not the nearest.
// BEGIN ANSWER
    Answer best;  // object -1, t = kNoHit
    for (int id = 0; id < scene.size(); ++id) {
        // Convexity: a ray leaving a surface cannot meet it again
        if (id == q.origin.object && !q.origin.inside) continue;
        ++n.intersectionTests;
        const double t = scene.intersect(q.ray, id, q.origin);
        if (t < q.tmax && best.object < 0) best = {id, t};
    }
    return best;
// END ANSWER
