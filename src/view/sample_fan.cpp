#include "view/sample_fan.h"

#include <algorithm>

#include "geometry/intersection.h"
#include "search/accelerator.h"
#include "trace/image_accumulator.h"

namespace rc {

int SampleFan::count(FanOutcome o) const {
    return int(std::count_if(rays.begin(), rays.end(), [o](const FanRay& r) { return r.outcome == o; }));
}

int SampleFan::count(rc::RayKind k) const {
    return int(std::count_if(rays.begin(), rays.end(), [k](const FanRay& r) { return r.kind == k; }));
}

SampleFan SampleFan::trace(const rc::RenderSession& session, int pixel, int maxRays) {
    SampleFan fan;
    fan.pixel = pixel;
    const rc::Scene& scene = session.scene();  // its lights carry the render's radius
    const rc::RenderOptions& o = session.options();
    const rc::Sampling& sampling = o.shading.sampling;
    fan.shadowSamples = sampling.shadowSamples;
    for (const rc::Light& l : scene.lights) fan.lights.push_back({l.position, l.radius});
    if (pixel < 0 || pixel >= session.width() * session.height()) return fan;
    // A complete search answers every ray (Embree's single precision may differ: linear)
    const auto search =
        rc::makeCompleteSearch(o.accel == rc::AccelKind::Embree ? rc::AccelKind::Linear : o.accel, scene);
    rc::Counters scratch;
    rc::ImageAccumulator image(session.width(), session.height(), pixel / session.width(),
                               pixel / session.width() + 1);

    // The pixel's eye samples, as the render makes them: same jitter, same keys
    const int spp = sampling.spp;
    std::vector<std::pair<rc::RayTask, int>> level, next;  // a task and its parent's index
    for (int k = 0; k < spp; ++k)
        level.push_back({rc::primaryTask(session.primaryRay(pixel, k), pixel, k, rc::eyeKey(sampling.seed, pixel, k),
                                         spp > 1 ? 1.0 / spp : 1.0),
                         -1});
    std::vector<rc::RayTask> children;
    // Depth by depth: answer each ray with the complete search, shade it for its children
    while (!level.empty()) {
        for (const auto& [task, parent] : level) {
            if (int(fan.rays.size()) >= maxRays) {
                fan.cut = true;
                return fan;
            }
            const rc::Query& q = task.query;
            const rc::Answer a = search->nearest(q, scratch);
            FanRay r;
            r.from = q.ray.o;
            r.kind = q.kind;
            r.parent = parent;
            r.depth = task.depth;
            r.sample = task.sample;
            r.light = q.light;
            r.hit = a.object;
            if (q.kind == rc::RayKind::Shadow) {
                r.aim = q.ray.at(q.tmax);
                r.to = a.object >= 0 ? q.ray.at(a.t) : r.aim;
                r.outcome = a.object >= 0 ? FanOutcome::Blocked : FanOutcome::Lit;
            } else if (a.object >= 0) {
                r.to = r.aim = q.ray.at(a.t);
                r.outcome = FanOutcome::Hit;
            } else {
                // Where it leaves the scene's bounding sphere
                const rc::SphereRoots roots = rc::sphereRootsStable(q.ray, scene.bound);
                r.to = r.aim = q.ray.at(roots.hit ? std::max(0.0, roots.t1) : 0.0);
                r.outcome = FanOutcome::Missed;
            }
            const int index = int(fan.rays.size());
            fan.rays.push_back(r);
            children.clear();
            rc::shade(scene, task, a, o.shading, image, children);
            // A hit sends K shadow rays to each spherical light, one to a point light; the
            // ones it did not send had their light's point behind the surface
            if (q.kind != rc::RayKind::Shadow && a.object >= 0) {
                int wanted = 0;
                for (const rc::Light& l : scene.lights) wanted += l.radius > 0.0 ? sampling.shadowSamples : 1;
                fan.notCast += wanted - int(std::count_if(children.begin(), children.end(), [](const rc::RayTask& c) {
                                   return c.query.kind == rc::RayKind::Shadow;
                               }));
            }
            for (const rc::RayTask& c : children) next.push_back({c, index});
        }
        level.swap(next);
        next.clear();
    }
    return fan;
}

}  // namespace rc
