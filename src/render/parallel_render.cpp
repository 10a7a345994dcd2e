#include "render/parallel_render.h"

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

namespace rc {

namespace {
constexpr int kBatch = 4096;  ///< rays a worker traces between reporting its progress and looking at cancelling

/// Each session on a thread of its own, while the calling thread hears progress.
void runOnThreads(std::vector<std::unique_ptr<RenderSession>>& sessions, const std::function<bool(double)>& progress) {
    const int threads = int(sessions.size());
    // A session belongs to its thread until the join; the calling thread sees only these
    // (each worker's fraction done, and under the lock how many run and whether one has
    // news) and, after the join, the sessions themselves
    std::atomic<bool> cancel{false};
    std::vector<std::atomic<double>> fraction(static_cast<std::size_t>(threads));
    std::vector<std::exception_ptr> failure(static_cast<std::size_t>(threads));
    std::mutex lock;
    std::condition_variable posted;
    int running = threads;
    bool news = false;
    std::vector<std::thread> pool;
    for (int k = 0; k < threads; ++k) {
        fraction[k].store(0.0);
        pool.emplace_back([&, k] {
            RenderSession& s = *sessions[k];
            try {
                while (!cancel.load(std::memory_order_relaxed)) {
                    int n = 0;
                    while (n < kBatch && s.step()) ++n;
                    fraction[k].store(s.progress(), std::memory_order_relaxed);
                    if (s.done()) break;
                    // Wake the caller to report progress (and to hear whether to stop)
                    if (progress) {
                        {
                            std::lock_guard<std::mutex> hold(lock);
                            news = true;
                        }
                        posted.notify_one();
                    }
                }
            } catch (...) {  // e.g. std::bad_alloc: stop the others and rethrow on the caller
                failure[k] = std::current_exception();
                cancel = true;
            }
            {
                std::lock_guard<std::mutex> hold(lock);
                --running;
            }
            posted.notify_one();
        });
    }
    // Sleep until a worker has news or every worker is done: no polling
    std::unique_lock<std::mutex> hold(lock);
    while (running > 0) {
        posted.wait(hold, [&] { return news || running == 0; });
        news = false;
        if (progress && !cancel.load()) {
            hold.unlock();
            double done = 0.0;
            for (const auto& f : fraction) done += f.load(std::memory_order_relaxed);
            if (!progress(done / threads)) cancel = true;
            hold.lock();
        }
    }
    hold.unlock();
    for (std::thread& t : pool) t.join();
    for (const std::exception_ptr& e : failure)
        if (e) std::rethrow_exception(e);
}
}  // namespace

ParallelRun renderParallel(std::shared_ptr<const Scene> scene, const RenderOptions& options, int threads,
                           BeamTreeBuilder* beams, const std::function<bool(double)>& progress) {
    // The full image size, resolved the way a session resolves it
    RenderOptions base = options;
    // Spherical lights: one copy of the scene for every thread
    scene = withLightRadius(std::move(scene), base.shading.sampling.lightRadius);
    if (base.width <= 0) base.width = scene->camera.width;
    if (base.height <= 0) base.height = scene->camera.height;
    if (threads <= 0) threads = int(std::max(1u, std::thread::hardware_concurrency()));
    threads = std::clamp(threads, 1, base.height);

    // [parallel-split]
    // One session per thread over its own block of scanlines: own cache tree, own lists
    std::vector<std::unique_ptr<RenderSession>> sessions;
    std::vector<std::unique_ptr<BeamTreeBuilder>> builders;
    for (int k = 0; k < threads; ++k) {
        RenderOptions o = base;
        o.rowBegin = base.height * k / threads;
        o.rowEnd = base.height * (k + 1) / threads;
        sessions.push_back(std::make_unique<RenderSession>(scene, o));
        if (beams) {
            builders.push_back(std::make_unique<BeamTreeBuilder>(base.width, base.height));
            sessions.back()->addSink(builders.back().get());
        }
    }
    // One thread: the caller's, so that a render on one thread is the same render as a
    // session's own run()
    if (threads == 1) sessions[0]->run(progress);
    else runOnThreads(sessions, progress);
    // [parallel-split]

    // [parallel-merge]
    // Integer sums: the merged image is the same for any number of threads
    // Threads number the ray-tree paths in the order they meet them: map them to one tree
    CacheTree canonical;  // paths only: one per sample
    ParallelRun out;
    out.threads = threads;
    // One thread held every row: its image is the image
    if (threads == 1) out.image = sessions[0]->takeImage();
    else out.image = ImageAccumulator(base.width, base.height);
    for (int k = 0; k < threads; ++k) {
        const RenderSession& s = *sessions[k];
        if (threads > 1) out.image += s.image();
        out.counters += s.counters();
        out.queuePeak = std::max(out.queuePeak, s.order().queuePeak());
        out.regions += s.order().regions();
        const CacheTree& tree = s.cacheTree();
        std::vector<int> map(tree.size(), 0);
        for (int i = 0; i < tree.size(); ++i) {
            const CacheTree::Node& node = tree.node(i);
            map[i] = node.parent < 0 ? canonical.root(node.sample)
                                     : canonical.child(map[node.parent], node.kind, node.light, node.sample);
        }
        out.completed = out.completed && s.done();
        if (beams) beams->merge(std::move(*builders[k]), map);
    }
    // [parallel-merge]
    out.paths = canonical.size();
    if (progress && out.completed) progress(1.0);
    return out;
}

}  // namespace rc
