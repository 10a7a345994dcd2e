// The key and the shapes the Qt window draws at every stop of the shipped tours: the
// entries the window's key takes from the core match the shapes it drew, and the whole
// list is written (JSON, one object per stop) for tests/web/same_key.py, which holds it
// against the page's at the same stops. The file is RAYCACHE_KEYS_OUT, or
// raycache_native_keys.json in the temporary folder.
#include <catch2/catch.hpp>

#include <algorithm>
#include <set>
#include <string>

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QTreeWidgetItemIterator>

#include <nlohmann/json.hpp>

#include "gui_options.h"
#include "main_window.h"
#include "overlay_painter.h"
#include "ray_tree_panel.h"
#include "view/tour.h"
#include "window_fixture.h"

using namespace rcgui;
using rcgui::testing::showAt;
using rcgui::testing::toursFolder;

namespace {

bool hasKey(const std::vector<rc::LegendEntry>& keys, const std::string& prefix) {
    return std::any_of(keys.begin(), keys.end(), [&](const rc::LegendEntry& e) { return e.text.rfind(prefix, 0) == 0; });
}

}  // namespace

TEST_CASE("At every tour stop the window's key names the shapes it drew", "[gui][tour][same-key]") {
    nlohmann::json out = nlohmann::json::array();
    int withShapes = 0, withTree = 0;
    for (const char* name : {"hanrahan86", "debugging"}) {
        const rc::Tour tour = rc::loadTour(QDir(toursFolder()).filePath(QString(name) + ".json").toStdString());
        const std::vector<GuiOptions> stops = rcgui::testing::stopOptionsOf(tour);
        for (int k = 1; k <= int(tour.stops.size()); ++k) {
            INFO(name << " stop " << k);
            MainWindow w;
            showAt(w, 1280, 720);
            w.setTour(tour, stops);
            REQUIRE(w.goToStop(k, true));
            w.controller().wait();
            QApplication::processEvents();
            (void)w.grab();  // paints the view: its shapes, then its key
            const OverlayPainter& p = w.overlayPainter();
            std::set<std::string> roles;
            for (const rc::OverlayShape& s : p.drawnShapes()) roles.insert(rc::toString(s.role));
            const auto& keys = p.coreKeys();
            // The shapes' entries are there exactly when their shapes are drawn
            CHECK(hasKey(keys, "cylinder of safety") ==
                  (roles.count("Cylinder") + roles.count("CachedCylinder") + roles.count("CylinderAxis") > 0));
            CHECK(hasKey(keys, "target (") == (roles.count("Target") + roles.count("TargetPoint") > 0));
            CHECK(hasKey(keys, "potential blockers") == (roles.count("Blocker") + roles.count("BlockerHit") > 0));
            withShapes += !roles.empty();
            nlohmann::json texts = nlohmann::json::array();
            for (const rc::LegendEntry& e : keys) texts.push_back(e.text);
            nlohmann::json stop = {{"tour", name}, {"stop", k}, {"roles", roles}, {"keys", texts}};
            // The Ray tree panel's rows, where the stop shows it: path, hit, decision, tests (the
            // page leaves out the kind, which the path's last step names)
            if (const RayTreePanel* tree = w.rayTreePanel(); tree->isVisibleTo(&w)) {
                nlohmann::json rows = nlohmann::json::array();
                for (QTreeWidgetItemIterator it(const_cast<RayTreePanel*>(tree)); *it; ++it) {
                    nlohmann::json row = nlohmann::json::array();
                    for (int c : {0, 2, 3, 4}) row.push_back((*it)->text(c).toStdString());
                    rows.push_back(row);
                }
                CHECK(rows.size() > 1);
                stop["rayTree"] = rows;
                ++withTree;
            }
            out.push_back(stop);
        }
    }
    CHECK(withShapes >= 8);  // 10 stops ask for the cylinder or the hull
    CHECK(withTree >= 2);    // stops 1 and 6 of the paper's tour show the ray tree
    const QByteArray env = qgetenv("RAYCACHE_KEYS_OUT");
    const QString path = env.isEmpty() ? QDir::temp().filePath("raycache_native_keys.json") : QString::fromLocal8Bit(env);
    QFile f(path);
    REQUIRE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(QByteArray::fromStdString(out.dump(1)));
}
