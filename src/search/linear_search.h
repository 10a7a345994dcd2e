#pragma once
/// \file
/// \brief The linear search: the paper's "standard ray-tracing algorithm", every object tested.
#include <memory>
#include <string>

#include "search/complete_search.h"

namespace rc {

class BoundingVolumeHierarchy;
class ClearanceScan;
class SphereBatch;

/// Tests every object in the scene: the paper's "standard ray-tracing algorithm".
///
/// Rays only. The caches' region queries (which objects meet a blocker hull, a cylinder
/// of safety, an empty cone) are the caches' own bookkeeping, not a search for a ray: they
/// go through a hierarchy of bounding spheres built once per scene, so a cache builds a
/// list or a cylinder without measuring every object. (RayCache's choice: the paper does not
/// say how lists are found. `Regions::Scan` measures every object instead.)
/// Scenes of at most this many objects measure cylinders of safety by ClearanceScan.
inline constexpr int kClearanceScanLimit = 256;

class LinearSearch final : public CompleteSearch {
public:
    /// How region queries (cull(), clearance()) are answered.
    enum class Regions { Hierarchy, Scan };
    explicit LinearSearch(const Scene& scene, Regions regions = Regions::Hierarchy);
    ~LinearSearch() override;
    Answer nearest(const Query& q, Counters& n) const override;
    void cull(SphereCull& c) const override;
    double clearance(const Vec3& a, const Vec3& b, int skip, int skipToo, double cap,
                     double stopBelow = -kNoHit, int* nearest = nullptr) const override;
    std::string name() const override { return "linear"; }
    bool cheap() const override { return false; }

private:
    /// Every object, in id order (search/sphere_batch.h, which tests objects and so holds
    /// solution regions, is included only by the sources that test)
    std::unique_ptr<const SphereBatch> all_;
    /// The bounding spheres of the objects, for region queries (none: scan them all)
    std::unique_ptr<const BoundingVolumeHierarchy> regions_;
    /// Every bounding sphere, for the radius of a cylinder of safety (none: too many objects)
    std::unique_ptr<const ClearanceScan> scan_;
};

}  // namespace rc
