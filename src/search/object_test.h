#pragma once
/// \file
/// \brief One object tested against a ray: rc::testObject(), the standard algorithm's loop
/// body, and rc::clearlyMisses(), the quick rejection of a sphere by its stable discriminant.
/// Both answer a tutorial (01 and 06), so this header holds solution regions: only the
/// sources that test objects include it.
#include "search/query.h"
#include "search/standard_algorithm.h"

namespace rc {

/// The end of a test that is counted already: object `id`'s distance along `q`, kept in
/// `best` if it is a hit before q.tmax and nearer; the surface the ray leaves outward is no
/// hit (convexity). Inline in the instructor's build; the student's rc::standardTest()
/// (tutorial 01) in the student edition, its count not counted twice. The caches' probes
/// test their cached object with it.
inline void keepNearer(const Scene& scene, const Query& q, int id, Answer& best) {
    // BEGIN SOLUTION 01
    const double t = scene.intersect(q.ray, id, q.origin);
    if (t < q.tmax && nearer(t, id, best)) best = {id, t};
    // END SOLUTION
    // BEGIN STUB
    // Counters counted;  // the caller has counted this test
    // standardTest(scene, q, id, best, counted);
    // END STUB
}

/// Tests object `id` against `q` and keeps it in `best` if it is nearer. Counts the test;
/// a ray leaving a sphere or polygon it starts on is skipped for free (convexity). Every
/// search and cache tests its objects through it: inline in the instructor's build, the
/// student's rc::standardTest() (tutorial 01) in the student edition. (It does not call
/// keepNearer(): with that call inlined, the complete search's loop kept fewer of the
/// ray's coordinates in registers, more instructions a sphere under callgrind.)
inline void testObject(const Scene& scene, const Query& q, int id, Answer& best, Counters& n) {
    // BEGIN SOLUTION 01
    if (id == q.origin.object && !q.origin.inside) return;
    ++n.intersectionTests;
    const double t = scene.intersect(q.ray, id, q.origin);
    if (t < q.tmax && nearer(t, id, best)) best = {id, t};
    // END SOLUTION
    // BEGIN STUB
    // standardTest(scene, q, id, best, n);
    // END STUB
}

/// Does the ray (o, d) clearly miss the sphere centred at (cx, cy, cz) with squared radius
/// r2? Its stable discriminant, as sphereRootsStable() computes it, is negative by more than
/// a margin of rounding, which absorbs any difference in how the compiler fused this
/// arithmetic and the full test's. A sphere it does not reject may still be missed. (In the
/// student edition, where tutorial 06 is open, it rejects nothing: every sphere gets the
/// full test, with the same answers and counts.)
inline bool clearlyMisses(const Vec3& o, const Vec3& d, double cx, double cy, double cz, double r2) {
    // BEGIN SOLUTION 06
    const double fx = o.x - cx, fy = o.y - cy, fz = o.z - cz;
    const double b = fx * d.x + fy * d.y + fz * d.z;
    const double lx = fx - b * d.x, ly = fy - b * d.y, lz = fz - b * d.z;
    const double disc = r2 - (lx * lx + ly * ly + lz * lz);
    return disc < -1e-12 * (fx * fx + fy * fy + fz * fz + r2);
    // END SOLUTION
    // BEGIN STUB
    // (void)o, (void)d, (void)cx, (void)cy, (void)cz, (void)r2;
    // return false;
    // END STUB
}

/// What testObjectQuickly() does with object `id` once its quick rejection is known: `r2`
/// is its squared radius if it is a sphere (negative if it is not), `rejected` whether
/// clearlyMisses() rejected it, which counts only for a sphere the ray does not leave. For
/// loops that compute the rejection themselves, several spheres at a time.
inline void testRejected(const Scene& scene, const Query& q, int id, double r2, bool rejected, Answer& best,
                         Counters& n) {
    if (r2 < 0.0 || id == q.origin.object) {
        testObject(scene, q, id, best, n);  // a polygon, a cone, or the surface the ray leaves
        return;
    }
    ++n.intersectionTests;
    if (!rejected) keepNearer(scene, q, id, best);
}

/// testObject() with the quick rejection of a sphere the ray clearly misses: the same
/// answers and counts, for lists tested one object at a time.
inline void testObjectQuickly(const Scene& scene, const Query& q, int id, Answer& best, Counters& n) {
    const Object& obj = scene.objects[id];
    if (obj.shape != Shape::Sphere || id == q.origin.object) {
        testObject(scene, q, id, best, n);
        return;
    }
    ++n.intersectionTests;
    const Sphere& s = scene.spheres[obj.index];
    if (clearlyMisses(q.ray.o, q.ray.d, s.c.x, s.c.y, s.c.z, s.r * s.r)) return;
    keepNearer(scene, q, id, best);
}

}  // namespace rc
