// The renderer against a second implementation written apart from it: a plain recursive
// Whitted tracer (whitted_reference.h). Its nearest-hit loop is tutorial 01's answer in
// another form, so it is the instructor's: the student edition leaves tests/instructor/ out.
#include <catch2/catch.hpp>

#include <memory>

#include "render/parallel_render.h"
#include "render/render_session.h"
#include "scene/builtin_scenes.h"
#include "whitted_reference.h"

using namespace rc;

namespace {
RenderOptions sized(int w, int h) {
    RenderOptions opt;
    opt.width = w;
    opt.height = h;
    return opt;
}
std::shared_ptr<const Scene> shared(Scene s) { return std::make_shared<const Scene>(std::move(s)); }
}  // namespace

TEST_CASE("cube:3 and cube:4 are the image a plain recursive Whitted tracer makes", "[golden]") {
    // The oracle is a second implementation (whitted_reference.h): recursion, every
    // ray against every sphere, the shading written out again from the model
    for (const char* name : {"cube:3", "cube:4"}) {
        const auto scene = shared(makeBuiltin(name));
        RenderSession s(scene, sized(48, 40));
        s.run();
        const ImageAccumulator expected = testing::WhittedReference(*scene).render(48, 40);
        INFO(name);
        REQUIRE(s.image().rgb8() == expected.rgb8());
        for (int p = 0; p < 48 * 40; ++p) REQUIRE(s.image().value(p) == expected.value(p));
    }
}

TEST_CASE("with the distributed options at their defaults the image is the classic one", "[distributed]") {
    // The classic image of cube:4, rendered in parallel with default Sampling, is the one a
    // plain recursive Whitted tracer makes
    const auto cube = shared(loadScene("cube:4", 1986));
    const ParallelRun classic = renderParallel(cube, sized(48, 48), 1);
    REQUIRE(classic.image.rgb8() == testing::WhittedReference(*cube).render(48, 48).rgb8());
}
