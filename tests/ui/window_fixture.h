#pragma once
// What the GUI tests' fixtures share: showing a window and reaching its session.
#include <catch2/catch.hpp>

#include <vector>

#include <QApplication>
#include <QDir>

#include "gui_options.h"
#include "main_window.h"
#include "view/session_state.h"
#include "view/tour.h"

namespace rcgui::testing {

/// Shows `w` at width x height and lets it lay itself out.
inline void showAt(MainWindow& w, int width, int height) {
    w.resize(width, height);
    w.show();
    QApplication::processEvents();
}

/// The session `w` shows (the test fails if there is none).
inline rc::SessionState& stateOf(MainWindow& w) {
    rc::SessionState* s = w.controller().state();
    REQUIRE(s != nullptr);
    return *s;
}

/// The folder of the shipped tours.
inline QString toursFolder() { return QDir(RAYCACHE_SCENES_DIR "/../tours").absolutePath(); }

/// A shipped tour, e.g. shippedTour("hanrahan86.json").
inline rc::Tour shippedTour(const QString& file) {
    return rc::loadTour(QDir(toursFolder()).filePath(file).toStdString());
}

/// The options of every stop of `tour`, read as raycache-gui reads them (the test fails on
/// an error, and says which).
inline std::vector<GuiOptions> stopOptionsOf(const rc::Tour& tour) {
    std::vector<GuiOptions> stops;
    for (int k = 1; k <= int(tour.stops.size()); ++k) {
        QString why;
        const auto o = stopOptions(tour, k, GuiOptions{}, why);
        INFO("stop " << k << ": " << why.toStdString());
        REQUIRE(o);
        stops.push_back(*o);
    }
    return stops;
}

/// `w` as a projector shows it (1280x720, large fonts), with `tour` loaded.
inline void showTourAtProjector(MainWindow& w, const rc::Tour& tour) {
    w.setLargeFonts(true);
    showAt(w, 1280, 720);
    w.setTour(tour, stopOptionsOf(tour));
}

}  // namespace rcgui::testing
