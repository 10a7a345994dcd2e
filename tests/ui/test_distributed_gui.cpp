// GUI tests: distributed ray tracing's options (--spp, --light-radius, --gloss ...) reach the
// window's render, which then makes the image the core makes, and bad values are errors.
#include <catch2/catch.hpp>

#include <QTextStream>

#include "gui_options.h"
#include "main_window.h"
#include "render/parallel_render.h"
#include "scene/builtin_scenes.h"
#include "screenshot.h"
#include "view/session_state.h"

using namespace rcgui;

TEST_CASE("The GUI takes distributed ray tracing options and renders the core image", "[gui][cli][distributed]") {
    GuiOptions o;
    QString msg;
    REQUIRE(parseGuiOptions({"raycache-gui", "cube:2", "--width", "16", "--height", "16", "--spp", "2",
                             "--light-radius", "0.3", "--shadow-samples", "2", "--gloss", "4", "--gloss-samples", "2",
                             "--seed", "7", "--order", "scanline"},
                            o, msg) == ParseResult::Ok);
    REQUIRE(o.sampling.spp == 2);
    REQUIRE(o.sampling.lightRadius == 0.3);
    REQUIRE(o.sampling.shadowSamples == 2);
    REQUIRE(o.sampling.glossDegrees == 4.0);
    REQUIRE(o.sampling.glossSamples == 2);
    REQUIRE(o.sampling.seed == 7);
    for (const QStringList& bad : {QStringList{"--light-radius", "-1"}, QStringList{"--spp", "0"},
                                   QStringList{"--gloss", "nan"}, QStringList{"--gloss-samples", "two"},
                                   QStringList{"--shadow-samples", "65"}}) {
        GuiOptions b;
        INFO(bad.join(' ').toStdString());
        REQUIRE(parseGuiOptions(QStringList{"raycache-gui"} + bad, b, msg) == ParseResult::Error);
        REQUIRE(msg.contains(bad.front()));
    }
    // The window's render, run to the end, is the core's image
    MainWindow w;
    QString errors;
    QTextStream err(&errors);
    o.steps = 1000000000;
    REQUIRE(applyOptions(w, o, err));
    rc::SessionState* s = w.controller().state();
    REQUIRE(s);
    REQUIRE(s->session().done());
    rc::RenderOptions core;
    core.width = core.height = 16;
    core.cache = o.cache;
    core.order = rc::OrderKind::Scanline;
    core.shading.sampling = o.sampling;
    const rc::ParallelRun run =
        rc::renderParallel(std::make_shared<const rc::Scene>(rc::loadScene("cube:2", 1986)), core, 1);
    REQUIRE(s->session().image().rgb8() == run.image.rgb8());
    // and not the classic one
    core.shading.sampling = rc::Sampling{};
    REQUIRE(s->session().image().rgb8() !=
            rc::renderParallel(std::make_shared<const rc::Scene>(rc::loadScene("cube:2", 1986)), core, 1).image.rgb8());
}
