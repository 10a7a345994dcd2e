#pragma once
/// \file
/// \brief The sample rays of one pixel (distributed ray tracing): its eye samples, the
/// shadow rays of every hit fanning to points of the light's sphere, and its glossy
/// reflections, re-traced through the core for the overlays and the scene view.
#include <vector>

#include "geometry/sphere.h"
#include "render/render_session.h"

namespace rc {

/// What became of one sample ray.
enum class FanOutcome {
    Hit,      ///< an eye, reflection or refraction ray that hit an object
    Missed,   ///< one that hit nothing: it leaves the scene
    Lit,      ///< a shadow ray that reached its point of the light
    Blocked,  ///< a shadow ray that an object stopped
};

/// One ray of a pixel's samples.
struct FanRay {
    rc::Vec3 from{0.0};  ///< where it starts (the eye, or the hit it was spawned at)
    rc::Vec3 to{0.0};    ///< where it stops: its hit, its point of the light, or the scene's edge
    rc::Vec3 aim{0.0};   ///< shadow rays: the point of the light's sphere it goes to (else `to`)
    rc::RayKind kind = rc::RayKind::Primary;
    FanOutcome outcome = FanOutcome::Hit;
    int parent = -1;     ///< index of the ray that spawned it (-1: an eye sample)
    int depth = 1;       ///< the eye sample is depth 1
    int sample = 0;      ///< its index among its parent's rays of its kind (eye rays: the pixel sample)
    int light = -1;      ///< shadow rays: the light
    int hit = -1;        ///< the object hit, -1 for none
};

/// Every ray of one pixel's samples, in the order of their depth (all eye samples first).
/// The rays are the render's own: the same pixel samples, light points and gloss
/// directions (a pure function of the seed and the ray's path), answered by a complete
/// search, so a re-trace costs nothing in the render's hot path.
struct SampleFan {
    /// At most this many rays are re-traced (glossy reflection branches at every depth).
    static constexpr int kMaxRays = 4096;
    /// Fans of more rays are drawn in hairlines, without a halo: a wider pen is filled as
    /// a path, and thousands of them take seconds to paint.
    static constexpr int kHaloRays = 200;

    int pixel = -1;
    std::vector<FanRay> rays;
    std::vector<rc::Sphere> lights;  ///< every light's sphere (radius 0: a point light)
    int shadowSamples = 1;           ///< shadow rays per spherical light and hit
    /// Shadow samples of the hits that got no ray: the light's point lies behind the
    /// surface, or it would bring nothing.
    int notCast = 0;
    bool cut = false;                ///< stopped at the ray limit: deeper rays are missing

    int count(FanOutcome o) const;
    int count(rc::RayKind k) const;

    /// The sample rays of `pixel` of `session`'s render (its scene, options and seed).
    static SampleFan trace(const rc::RenderSession& session, int pixel, int maxRays = kMaxRays);
};

}  // namespace rc
