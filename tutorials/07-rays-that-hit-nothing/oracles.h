#pragma once
// Tutorial 07's oracles: the widest empty cone, and the yardstick of the challenge. Their
// answers are data (oracle_data.txt, oracle_data.h), recorded by the instructor's oracles.
#include <vector>

#include "geometry/ray.h"
#include "geometry/sphere.h"
#include "scene/camera.h"

namespace tutorial {

/// The half-angle of the widest cone around `axis` from `apex` whose rays meet none of
/// `spheres`, found by turning a ray from the axis towards each sphere until it meets it
/// (negative: the ray along the axis meets one, or the apex is inside one; infinity: no
/// spheres).
double oracleConeAngle(const rc::Vec3& apex, const rc::Vec3& axis, const std::vector<rc::Sphere>& spheres);

/// The yardstick of the challenge: the design notes' one exact answer, the empty cone of the
/// last eye ray that hit nothing, counted over the eye rays in scanline order. A ray inside
/// the cone is answered; any other is searched, and an empty one, searched, makes the new
/// cone with one look at every sphere (one more complete search).
struct OneCone {
    long searches = 0, emptySearches = 0;
    double cost = 0.0;  ///< complete searches, counting its n tests per new cone as one
};
OneCone oneCone(const std::vector<rc::Sphere>& spheres, const rc::Camera& camera, int width, int height);

/// The sphere each eye ray of the image hits first, in scanline order (-1: none; equal
/// distances: the lower index): the complete search's answers.
std::vector<int> eyeHits(const std::vector<rc::Sphere>& spheres, const rc::Camera& camera, int width, int height);

/// The cylinder of safety's row in the table of intermediate's yardsticks: Speer, DeRose and
/// Barsky's cylinder for a ray that hits nothing (the segment from the eye to where the ray
/// leaves the spheres' bounding sphere, as thick as the gap to the nearest sphere), counted
/// as the check counts a cache (its constructor makes 3n tests, each new cylinder n).
struct CylinderRow {
    double cost = 0.0, emptyCost = 0.0, searchesPerBeam = 0.0, testsPerAnswer = 0.0;
    long searches = 0, tests = 0, afterEmptyAnswered = 0, afterEmpty = 0;
};
CylinderRow cylinderRow(const std::vector<rc::Sphere>& spheres, const rc::Camera& camera, int width, int height);

/// The 4-connected pieces of pixels whose eye rays hit nothing (truth[p] < 0): the beams
/// of empty eye rays.
long emptyBeams(int width, int height, const std::vector<int>& truth);

}  // namespace tutorial
