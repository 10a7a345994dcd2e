// GUI tests of the tours' claims: every stop of the shipped tours rendered in the window as
// a lecture shows it, each claim read from what the stop draws (view/claim.h), and each
// caption checked for paths, panes and counts that the stop does not draw.
#include <catch2/catch.hpp>

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QTemporaryDir>

#include "gui_options.h"
#include "main_window.h"
#include "view/claim.h"
#include "view/tour.h"
#include "window_fixture.h"

using namespace rcgui;
using rcgui::testing::showAt;
using rcgui::testing::shippedTour;
using rcgui::testing::stopOptionsOf;
using rcgui::testing::toursFolder;

namespace {

/// What stop `k` of the window's tour draws, as the claims read it: its panes and the
/// selection they share.
rc::ClaimView viewOf(MainWindow& w, const rc::TourStop& stop) {
    rc::ClaimView v = rc::claimViewOf(stop);
    v.panes.push_back({w.controller().state(), w.selection()});
    if (w.compareChoice()) v.panes.push_back({w.compareController().state(), w.selection()});
    for (const rc::ClaimPane& p : v.panes) REQUIRE(p.state != nullptr);
    return v;
}

/// The results of every claim of stop `k` (from 1), shown in `w` as written.
std::vector<rc::ClaimResult> claimsAt(MainWindow& w, const rc::Tour& tour, int k, std::vector<std::string>* slips = nullptr) {
    REQUIRE(w.goToStop(k, true));
    const rc::TourStop& stop = tour.stops[std::size_t(k - 1)];
    std::vector<rc::Claim> claims;
    const std::string error = rc::parseStopClaims(stop, claims);
    INFO("stop " << k << ": " << error);
    REQUIRE(error.empty());
    const rc::ClaimView view = viewOf(w, stop);
    std::vector<rc::ClaimResult> out;
    for (const rc::Claim& c : claims) out.push_back(rc::checkClaim(c, view));
    if (slips) *slips = rc::captionSlips(stop.caption, claims, view);
    return out;
}

}  // namespace

TEST_CASE("Every claim of the shipped tours holds in the window, and every caption names only what its stop draws",
          "[gui][tour][claims]") {
    int claimed = 0, stops = 0;
    for (const QString& file : {QString("hanrahan86.json"), QString("debugging.json")}) {
        const rc::Tour tour = shippedTour(file);
        MainWindow w;
        showAt(w, 1280, 720);
        w.setTour(tour, stopOptionsOf(tour));
        for (int k = 1; k <= int(tour.stops.size()); ++k) {
            std::vector<std::string> slips;
            for (const rc::ClaimResult& r : claimsAt(w, tour, k, &slips)) {
                INFO(file.toStdString() << " stop " << k << ": " << r.text << ": " << r.reading);
                REQUIRE(r.holds);
                ++claimed;
            }
            for (const std::string& slip : slips) {
                INFO(file.toStdString() << " stop " << k << ": " << slip);
                FAIL_CHECK("a caption names what its stop does not draw");
            }
            REQUIRE(slips.empty());
            ++stops;
        }
    }
    REQUIRE(stops >= 17);
    REQUIRE(claimed >= stops);  // every stop asserts something its picture shows
}

TEST_CASE("A wrong claim fails: stop 8 of the paper's tour with its panes swapped", "[gui][tour][claims]") {
    rc::Tour tour = shippedTour("hanrahan86.json");
    rc::TourStop& stop = tour.stops[7];
    REQUIRE(!stop.claims.empty());
    REQUIRE(stop.claims.front() == "right.misses < left.misses");
    MainWindow w;
    showAt(w, 1280, 720);
    w.setTour(tour, stopOptionsOf(tour));
    const auto right = claimsAt(w, tour, 8);
    REQUIRE(right.front().holds);
    stop.claims.front() = "left.misses < right.misses";
    w.setTour(tour, stopOptionsOf(tour));
    const auto swapped = claimsAt(w, tour, 8);
    INFO(swapped.front().reading);
    REQUIRE_FALSE(swapped.front().holds);
    // Both panes mark the misses of their eye rays: the comparison is of like with like
    const rc::ClaimView view = viewOf(w, stop);
    REQUIRE(view.panes.size() == 2);
    REQUIRE(rc::focusPath(view.panes[0]) == "eye");
    REQUIRE(rc::focusPath(view.panes[1]) == "eye");
}

TEST_CASE("A caption that names a pane, path or count its stop does not draw is caught", "[gui][tour][claims]") {
    const rc::Tour tour = rc::parseTour(R"({"stops": [
  {"title": "One", "caption": "Left: this. The eye/reflection ray misses 12 times.", "scene": "pair",
   "cache": "blocker", "order": "scanline", "steps": 3000, "select": "32,32", "claims": ["objects == 2"]}]})",
                                        "t.json");
    MainWindow w;
    showAt(w, 1280, 720);
    w.setTour(tour, stopOptionsOf(tour));
    std::vector<std::string> slips;
    claimsAt(w, tour, 1, &slips);
    REQUIRE(slips.size() == 3);
    REQUIRE(slips[0].find("Left pane") != std::string::npos);
    REQUIRE(slips[1].find("eye/reflection") != std::string::npos);
    REQUIRE(slips[2].find("'12'") != std::string::npos);
}

namespace {

/// A tour of six stops on `pair` whose stop 5 is `bad` (a JSON object's inside).
QString tourWithBadStop5(const QString& bad) {
    QString stops;
    for (int k = 1; k <= 6; ++k) {
        const QString body = k == 5 ? bad : QString(R"("scene": "pair", "width": 64, "height": 64, "select": "32,32")");
        stops += QString(R"(%1
  {"title": "Stop %2", "caption": "c.", %3})").arg(k > 1 ? "," : "").arg(k).arg(body);
    }
    return "{\"stops\": [" + stops + "]}\n";
}

}  // namespace

TEST_CASE("A tour with a bad stop 5 fails when it is opened, naming stop 5 and its field", "[gui][tour][cli]") {
    QTemporaryDir dir;
    struct Case {
        QString stop, field;
    };
    const std::vector<Case> cases = {
        {R"("scene": "no_such_scene.nff")", "scene"},
        {R"("scene": "pair", "width": 64, "height": 64, "select": "64,10")", "select"},
        {R"("scene": "pair", "width": 64, "height": 64, "select": "32,32:eye/refraction")", "select"},
        {R"("scene": "pair", "focus": "0,0,900,10")", "focus"},
        {R"("scene": "pair", "overlays": ["cone"], "claims": ["right.blockers > 1"])", "claims"},
        {R"("scene": "pair", "claims": ["blockers > 1"])", "claims"},
    };
    for (const Case& c : cases) {
        const QString file = dir.filePath("bad.json");
        QFile f(file);
        REQUIRE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
        f.write(tourWithBadStop5(c.stop).toUtf8());
        f.close();
        // Read and checked in the core, as any front end opens it
        const rc::Tour tour = rc::loadTour(file.toStdString());
        try {
            rc::checkTour(tour);
            FAIL("stop 5 was accepted: " << c.stop.toStdString());
        } catch (const rc::TourError& e) {
            INFO(e.what());
            REQUIRE(e.line == 6);
            REQUIRE(QString(e.what()).contains("stop 5 (Stop 5): " + c.field + ": "));
        }
        // The window's command line: exit 2 before the first stop is shown
        QProcess gui;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("QT_QPA_PLATFORM", "offscreen");
        gui.setProcessEnvironment(env);
        gui.start(RAYCACHE_GUI, {"--tour", file, "--screenshot", dir.filePath("never.png")});
        REQUIRE(gui.waitForFinished(60000));
        const QString err = QString::fromUtf8(gui.readAllStandardError());
        INFO(err.toStdString());
        REQUIRE(gui.exitCode() == 2);
        REQUIRE(err.contains(file + ":6:"));
        REQUIRE(err.contains("stop 5 (Stop 5): " + c.field));
        REQUIRE_FALSE(QFileInfo::exists(dir.filePath("never.png")));
    }
}

TEST_CASE("A tour's relative scene path resolves against the tour file", "[gui][tour]") {
    QTemporaryDir dir;
    REQUIRE(QDir(dir.path()).mkpath("lecture/scenes"));
    QFile nff(dir.filePath("lecture/scenes/one.nff"));
    REQUIRE(nff.open(QIODevice::WriteOnly));
    nff.write("v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 32 32\nl 3 3 3\nf 1 0 0 0.5 0.5 10 0 0\ns 0 0 0 1\n");
    nff.close();
    const QString file = dir.filePath("lecture/t.json");
    QFile f(file);
    REQUIRE(f.open(QIODevice::WriteOnly));
    f.write(R"({"stops": [{"title": "One", "caption": "c.", "scene": "scenes/one.nff", "select": "16,16"}]})");
    f.close();
    const rc::Tour tour = rc::loadTour(file.toStdString());
    REQUIRE_NOTHROW(rc::checkTour(tour));
    QString why;
    const auto o = stopOptions(tour, 1, GuiOptions{}, why);
    REQUIRE(o);
    REQUIRE(QFileInfo(o->scene).canonicalFilePath() == QFileInfo(dir.filePath("lecture/scenes/one.nff")).canonicalFilePath());
}
