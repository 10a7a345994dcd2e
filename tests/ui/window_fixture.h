#pragma once
// What the GUI tests' fixtures share: showing a window and reaching its session.
#include <catch2/catch.hpp>

#include <QApplication>

#include "main_window.h"
#include "view/session_state.h"

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

}  // namespace rcgui::testing
