// The toy cache of toy_cache.cpp in the GUI: linked into the window as adding_a_cache.md
// says (one file more, nothing else told), the Cache menu offers it, the command line takes
// it, and the window renders with it.
#include <catch2/catch.hpp>

#include <QApplication>

#include "gui_options.h"
#include "main_window.h"
#include "search/cache_registry.h"
#include "view/session_state.h"

using namespace rcgui;

TEST_CASE("the toy cache is in the GUI's Cache menu and on its command line", "[registry][gui]") {
    MainWindow w;
    w.resize(1280, 720);
    w.show();
    QApplication::processEvents();
    // The menu is the registry, the toy last
    const QStringList offered = w.cacheChoices();
    REQUIRE(offered.size() == int(rc::cacheRegistry().size()));
    REQUIRE(offered.back() == "toy");
    // The command line takes it as it takes a built-in cache, and refuses a name not registered
    GuiOptions o;
    QString why;
    REQUIRE(parseGuiOptions({"raycache-gui", "--cache", "toy"}, o, why) == ParseResult::Ok);
    GuiOptions bad;
    REQUIRE(parseGuiOptions({"raycache-gui", "--cache", "toys"}, bad, why) == ParseResult::Error);
    REQUIRE(why.contains("toy"));  // the error lists the choices, the toy among them
}
