#include "view/implied_ray.h"

#include <vector>

#include "trace/distributed_sampling.h"
#include "trace/image_accumulator.h"
#include "trace/shading.h"

namespace rc {

bool raysImplied(const rc::RenderSession& session) { return session.options().accel != rc::AccelKind::Embree; }

std::optional<ImpliedRay> impliedRay(const rc::RenderSession& session, int pixel, int node) {
    const rc::CacheTree& tree = session.cacheTree();
    if (pixel < 0 || pixel >= session.width() * session.height() || node < 0 || node >= tree.size()) return std::nullopt;
    // [implied-ray]
    // The path from its eye ray down: each step a ray kind, light and sample index
    std::vector<int> path;
    for (int n = node; n >= 0; n = tree.node(n).parent) path.push_back(n);
    const rc::RenderOptions& o = session.options();
    const rc::Sampling& sampling = o.shading.sampling;
    const int sample = tree.node(path.back()).sample;
    rc::RayTask task = rc::primaryTask(session.primaryRay(pixel, sample), pixel, sample,
                                       rc::eyeKey(sampling.seed, pixel, sample), sampling.spp > 1 ? 1.0 / sampling.spp : 1.0);
    // Down the path: answer the ray, shade it, follow the child the path names (the cache
    // tree's child() keys a child path on the same three)
    const rc::CompleteSearch& search = session.completeSearch();
    rc::Counters scratch;
    rc::ImageAccumulator image(session.width(), session.height(), pixel / session.width(), pixel / session.width() + 1);
    std::vector<rc::RayTask> children;
    for (std::size_t k = path.size() - 1; k-- > 0;) {
        const rc::CacheTree::Node& step = tree.node(path[k]);
        children.clear();
        rc::shade(session.scene(), task, search.nearest(task.query, scratch), o.shading, image, children);
        const rc::RayTask* next = nullptr;
        for (const rc::RayTask& c : children)
            if (c.query.kind == step.kind && c.query.light == step.light && c.sample == step.sample) next = &c;
        if (!next) return std::nullopt;
        task = *next;
    }
    // [implied-ray]
    task.node = node;
    const rc::Answer nearest = search.nearest(task.query, scratch);
    return ImpliedRay{task, nearest};
}

}  // namespace rc
