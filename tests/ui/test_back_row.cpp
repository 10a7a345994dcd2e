// GUI tests of the tours as the back row of a lecture hall sees them, read from the layout
// the painters record (not by eye): at 1280x720 with large fonts, the scene view's labels
// cover neither each other, nor its caption, nor its controls; the image views' info box,
// key and colour bar cover neither the picture nor each other; the legend's lines are as
// tall in a window as in a screenshot; the Cache tree panel shows its entries and their
// state, flushes marked.
#include <catch2/catch.hpp>

#include <QDir>
#include <QHeaderView>
#include <QImage>
#include <QLabel>
#include <QPainter>

#include "cache_tree_panel.h"
#include "gui_options.h"
#include "image_view.h"
#include "legend_layout.h"
#include "overlay_painter.h"
#include "stats_panel.h"
#include "main_window.h"
#include "scene_view.h"
#include "view/tour.h"
#include "window_fixture.h"

using namespace rcgui;
using rcgui::testing::showAt;
using rcgui::testing::shippedTour;
using rcgui::testing::stopOptionsOf;
using rcgui::testing::showTourAtProjector;

namespace {

/// What is wrong with an image view's layout in a view of rectangle `view`: a box outside
/// the view, over the picture's drawn content, or over another box (empty: nothing).
std::vector<std::string> layoutFaults(const QRectF& view, const LegendLayout& l) {
    std::vector<std::string> faults;
    const std::vector<QRectF> boxes = l.boxes();
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        if (!view.contains(boxes[i])) faults.push_back("box " + std::to_string(i) + " leaves the view");
        if (boxes[i].intersects(l.picture)) faults.push_back("box " + std::to_string(i) + " covers the picture");
        for (std::size_t j = i + 1; j < boxes.size(); ++j)
            if (boxes[i].intersects(boxes[j])) faults.push_back("boxes " + std::to_string(i) + " and " + std::to_string(j) + " overlap");
    }
    return faults;
}

/// Checks the layout an image view's painter recorded at its last paint; returns its boxes.
int checkImageView(const ImageView* v, const OverlayPainter& painter) {
    if (!v || !v->isVisible()) return 0;
    const LegendLayout& l = painter.legendLayout();
    // The layout's picture is where the view draws the image
    REQUIRE(l.picture == v->shownImageRect().intersected(QRectF(v->rect())));
    REQUIRE_FALSE(l.picture.isEmpty());
    const std::vector<std::string> faults = layoutFaults(QRectF(v->rect()), l);
    for (const std::string& f : faults) INFO(f);
    REQUIRE(faults.empty());
    return int(l.boxes().size());
}

}  // namespace

TEST_CASE("At 1280x720 with large fonts no label of the scene view covers another, its caption or its controls, "
          "and no box of an image view covers its picture or another box",
          "[gui][tour][layout]") {
    int views = 0, labels = 0, imageStops = 0, boxes = 0;
    for (const QString& file : {QString("hanrahan86.json"), QString("debugging.json")}) {
        const rc::Tour tour = shippedTour(file);
        MainWindow w;
        showTourAtProjector(w, tour);
        for (int k = 1; k <= int(tour.stops.size()); ++k) {
            REQUIRE(w.goToStop(k, true));
            QApplication::processEvents();
            INFO(file.toStdString() << " stop " << k);
            // The image views: a paint places the boxes and asks for room, a second uses it
            w.grab();
            QApplication::processEvents();
            w.grab();
            {
                const int n = checkImageView(w.imageView(), w.overlayPainter()) +
                              checkImageView(w.compareView(), w.compareOverlayPainter());
                REQUIRE(n >= 1);  // the info box at least
                boxes += n;
                ++imageStops;
            }
            SceneView* sv = w.sceneView();
            if (!sv || !sv->isVisible()) continue;
            sv->grab();  // paints, recording the layout
            ++views;
            // The scene is drawn below its caption, never beneath it
            REQUIRE_FALSE(sv->captionRect().intersects(sv->drawingRect()));
            REQUIRE(sv->drawingRect().height() > sv->height() / 3);
            const std::vector<QRectF>& r = sv->labelRects();
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
    REQUIRE(imageStops == 18);  // every stop of both tours
    REQUIRE(boxes > imageStops);
}

TEST_CASE("The image view's layout check catches a key over the picture and boxes over each other", "[gui][layout]") {
    // A layout from the rule, then broken two ways
    LegendBlock info, key;
    info.naturalWidth = key.naturalWidth = 200;
    info.height = key.height = [](double) { return 100.0; };
    const QRectF view(0, 0, 1000, 600), picture(0, 0, 600, 600);
    const LegendLayout good = layOutLegend(view, picture, info, key, LegendBlock{});
    REQUIRE(good.fits);
    REQUIRE(layoutFaults(view, good).empty());
    LegendLayout over = good;
    over.key.moveTopLeft(QPointF(16, 480));  // the old rule's key: bottom left, over the picture
    REQUIRE(layoutFaults(view, over) == std::vector<std::string>{"box 1 covers the picture"});
    LegendLayout piled = good;
    piled.key.moveTop(good.info.top() + 50);
    REQUIRE(layoutFaults(view, piled) == std::vector<std::string>{"boxes 0 and 1 overlap"});
    // Boxes too tall for the column are cut at its bottom, not moved over the picture
    info.height = key.height = [](double) { return 400.0; };
    const LegendLayout tall = layOutLegend(view, picture, info, key, LegendBlock{});
    REQUIRE_FALSE(tall.fits);
    REQUIRE(layoutFaults(view, tall).empty());
}

TEST_CASE("The legend's lines are as tall in a shown window as in a screenshot, on a screen of any resolution",
          "[gui][tour][layout]") {
    const rc::Tour tour = shippedTour("hanrahan86.json");
    MainWindow w;
    showTourAtProjector(w, tour);
    REQUIRE(w.goToStop(2, true));
    // A first paint asks for room beside the picture, the view makes it
    w.grab();
    QApplication::processEvents();
    ImageView* v = w.imageView();
    // The shown window's own paint
    v->repaint();
    const double window = w.overlayPainter().legendLayout().lineHeight;
    // The --screenshot path: the window grabbed into a pixmap
    w.grab();
    const double screenshot = w.overlayPainter().legendLayout().lineHeight;
    // A screen that reports 72 dots per inch (an X server may), not the offscreen 96: the
    // same legend painted by a painter of its own on an image of that resolution
    QImage low(v->size(), QImage::Format_ARGB32);
    low.setDotsPerMeterX(int(std::lround(72 / 0.0254)));
    low.setDotsPerMeterY(int(std::lround(72 / 0.0254)));
    OverlayPainter own;
    {
        QPainter p(&low);
        p.setFont(v->font());
        own.paintLegend(p, rcgui::testing::stateOf(w), w.overlays(), w.selection(), QRectF(v->rect()), v->shownImageRect());
    }
    const double lowDpi = own.legendLayout().lineHeight;
    REQUIRE(window > 0.0);
    REQUIRE(screenshot == window);
    REQUIRE(lowDpi == window);
    INFO("column " << w.overlayPainter().legendLayout().column.width() << " view " << v->width());
    // Large fonts read as 16 points at 96 per inch: the 22 px lines of the headless screenshot
    QFont large = v->font();
    large.setPixelSize(int(std::lround(large.pointSizeF() * 96.0 / 72.0)));
    REQUIRE(window >= QFontMetricsF(large).height());
}

TEST_CASE("Stop 7 shows the cache tree's entries and a flush: state and object in view, flushed entries marked",
          "[gui][tour][layout]") {
    const rc::Tour tour = shippedTour("hanrahan86.json");
    MainWindow w;
    showTourAtProjector(w, tour);
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
