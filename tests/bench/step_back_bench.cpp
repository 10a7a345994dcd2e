// How long Step back and Go to step (backwards) take in the GUI's session controller, late
// in a render. Not a test: run it by hand, e.g.
//   build/ui/raycache_step_back_bench cube:5 512 blocker bfs [spacing]
// It prints the time a run to the end takes with and without checkpoints, the time of each
// step back, and the memory the checkpoints take.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <QCoreApplication>

#include "scene/builtin_scenes.h"
#include "session_controller.h"

using namespace rcgui;
using Clock = std::chrono::steady_clock;

int main(int argc, char** argv) {
    QCoreApplication app(argc, argv);
    const std::string spec = argc > 1 ? argv[1] : "cube:5";
    const int size = argc > 2 ? std::atoi(argv[2]) : 512;
    rc::RenderOptions o;
    o.width = o.height = size;
    o.cache = rc::parseCacheKind(argc > 3 ? argv[3] : "blocker").value_or(rc::CacheKind::Blocker);
    o.order = rc::parseOrderKind(argc > 4 ? argv[4] : "bfs").value_or(rc::OrderKind::BreadthFirst);
    const std::int64_t spacing = argc > 5 ? std::atoll(argv[5]) : rc::StepCheckpoints::kEvery;
    auto scene = std::make_shared<const rc::Scene>(rc::loadScene(spec));
    // The cost of taking checkpoints: the same run with none after step 0
    for (std::int64_t every : {std::int64_t(1) << 40, spacing, std::int64_t(1) << 40, spacing}) {
        rc::SessionState s({scene, o, every});
        auto t = Clock::now();
        s.runUntil(rc::RunGoal::ToEnd, 0);
        std::printf("run to the end, checkpoints every %lld steps: %.2f s (%s)\n", (long long)every,
                    std::chrono::duration<double>(Clock::now() - t).count(), s.checkpointSummary().c_str());
    }
    SessionController c;
    c.reset({scene, o, spacing});
    auto t0 = Clock::now();
    c.start(rc::RunGoal::ToEnd);
    c.wait();
    const std::int64_t total = c.state()->session().steps();
    const double run = std::chrono::duration<double>(Clock::now() - t0).count();
    std::printf("%s %dx%d %s %s: %lld steps, run to the end %.2f s\n", spec.c_str(), size, size,
                std::string(rc::toString(o.cache)).c_str(), std::string(rc::toString(o.order)).c_str(),
                (long long)total, run);
    double worst = 0.0, sum = 0.0;
    int n = 0;
    // Step back from points spread over the render, the latest first
    for (double at : {0.999, 0.9, 0.75, 0.5, 0.25, 0.1}) {
        const std::int64_t from = std::int64_t(double(total) * at);
        c.goToStep(from);
        c.wait();
        auto t = Clock::now();
        c.stepBack();
        c.wait();
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t).count();
        worst = std::max(worst, ms);
        sum += ms;
        ++n;
        std::printf("step back from %lld to %lld: %.1f ms\n", (long long)from, (long long)c.state()->session().steps(), ms);
    }
    std::printf("step back: worst %.1f ms, mean %.1f ms\n", worst, sum / n);
    std::printf("%s\n", c.state()->checkpointSummary().c_str());
    return 0;
}
