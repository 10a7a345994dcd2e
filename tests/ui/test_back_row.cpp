// GUI tests of the tours as the back row of a lecture hall sees them, read from the layout
// the painters record (not by eye): at 1280x720 with large fonts, the scene view's labels
// cover neither each other, nor its caption, nor its controls; the Cache tree panel shows
// its entries and their state, flushes marked.
#include <catch2/catch.hpp>

#include <QDir>
#include <QHeaderView>
#include <QLabel>

#include "cache_tree_panel.h"
#include "gui_options.h"
#include "image_view.h"
#include "stats_panel.h"
#include "main_window.h"
#include "scene_view.h"
#include "view/tour.h"
#include "window_fixture.h"

using namespace rcgui;
using rcgui::testing::showAt;
using rcgui::testing::shippedTour;
using rcgui::testing::stopOptionsOf;

namespace {

}  // namespace

TEST_CASE("At 1280x720 with large fonts no label of the scene view covers another, its caption or its controls",
          "[gui][tour][layout]") {
    int views = 0, labels = 0;
    for (const QString& file : {QString("hanrahan86.json"), QString("debugging.json")}) {
        const rc::Tour tour = shippedTour(file);
        MainWindow w;
        w.setLargeFonts(true);
        showAt(w, 1280, 720);
        w.setTour(tour, stopOptionsOf(tour));
        for (int k = 1; k <= int(tour.stops.size()); ++k) {
            REQUIRE(w.goToStop(k, true));
            QApplication::processEvents();
            SceneView* sv = w.sceneView();
            if (!sv || !sv->isVisible()) continue;
            sv->grab();  // paints, recording the layout
            ++views;
            const std::vector<QRectF>& r = sv->labelRects();
            INFO(file.toStdString() << " stop " << k);
            REQUIRE(!r.empty());
            for (std::size_t i = 0; i < r.size(); ++i) {
                REQUIRE(QRectF(sv->rect()).contains(r[i]));
                REQUIRE_FALSE(r[i].intersects(sv->captionRect()));
                for (QWidget* c : sv->findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly))
                    if (c->isVisible()) REQUIRE_FALSE(r[i].intersects(QRectF(c->geometry())));
                for (std::size_t j = i + 1; j < r.size(); ++j) REQUIRE_FALSE(r[i].intersects(r[j]));
            }
            labels += int(r.size());
        }
    }
    REQUIRE(views >= 6);  // stops 3-6 of the paper's tour, 3-4 of the debugging one
    REQUIRE(labels >= 3 * views);
}

TEST_CASE("Stop 7 shows the cache tree's entries and a flush: state and object in view, flushed entries marked",
          "[gui][tour][layout]") {
    const rc::Tour tour = shippedTour("hanrahan86.json");
    MainWindow w;
    w.setLargeFonts(true);
    showAt(w, 1280, 720);
    w.setTour(tour, stopOptionsOf(tour));
    REQUIRE(w.goToStop(7, true));
    QApplication::processEvents();
    auto* panel = w.findChild<CacheTreePanel*>();
    REQUIRE(panel);
    REQUIRE(panel->isVisible());
    // The path, its state and the object it holds are on screen without scrolling
    for (int c = 0; c < 3; ++c) {
        INFO("column " << c);
        REQUIRE(panel->header()->sectionViewportPosition(c) + panel->header()->sectionSize(c) <= panel->viewport()->width());
    }
    int flushed = 0;
    bool focusFlushedBelow = false;
    for (QTreeWidgetItemIterator it(panel); *it; ++it) {
        if ((*it)->text(1) == "flushed") {
            ++flushed;
            REQUIRE((*it)->background(1).style() != Qt::NoBrush);
        }
        // The ray in focus (a flushed miss) is bold: its entry has been reloaded
        if ((*it)->font(0).bold()) focusFlushedBelow = true;
    }
    REQUIRE(flushed >= 1);
    REQUIRE(focusFlushedBelow);
}

TEST_CASE("Presenting enlarges the text beyond large fonts and keeps a stop's panels hidden until it ends",
          "[gui][tour][layout]") {
    const rc::Tour tour = shippedTour("hanrahan86.json");
    MainWindow w;
    w.setLargeFonts(true);
    showAt(w, 1280, 720);
    const double large = w.imageView()->font().pointSizeF();
    w.setTour(tour, stopOptionsOf(tour));
    w.setPresentation(true);
    REQUIRE(w.imageView()->font().pointSizeF() > large);
    REQUIRE(w.findChild<QLabel*>("tourCaption")->font().pointSizeF() > large);  // the caption a hall reads
    // Stop 7 names the Cache tree panel: hidden while presenting, back after
    REQUIRE(w.goToStop(7, true));
    QApplication::processEvents();
    auto* panel = w.findChild<CacheTreePanel*>();
    REQUIRE(panel);
    REQUIRE_FALSE(panel->isVisible());
    REQUIRE_FALSE(w.statsPanel()->isVisible());
    w.setPresentation(false);
    QApplication::processEvents();
    REQUIRE(panel->isVisible());
    REQUIRE(w.imageView()->font().pointSizeF() == large);
}
