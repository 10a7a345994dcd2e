// The GUI's command line: CLI11, with the options it shares with the CLI defined once
// (view/flag_definitions.h) and so the CLI's limits; a bad flag is one line and exit 2.
#include <catch2/catch.hpp>

#include <QProcess>
#include <QStringList>

#include "view/flag_definitions.h"
#include "gui_options.h"
#include "scene/nff_reader.h"

using namespace rcgui;

namespace {
ParseResult parse(QStringList args, GuiOptions& o, QString& message) {
    args.prepend("raycache-gui");
    return parseGuiOptions(args, o, message);
}
}  // namespace

TEST_CASE("The GUI's size, sample and search limits are the CLI's", "[gui][cli]") {
    const QString largest = QString::number(rc::NffLimits::maxResolution);
    const QString over = QString::number(rc::NffLimits::maxResolution + 1);
    GuiOptions o;
    QString why;
    REQUIRE(parse({"--width", largest, "--height", largest}, o, why) == ParseResult::Ok);
    REQUIRE(o.width == int(rc::NffLimits::maxResolution));
    for (const QStringList& bad : {QStringList{"--width", over}, QStringList{"--height", "0"}, QStringList{"--band", over},
                                   QStringList{"--spp", QString::number(rc::kMaxSpp + 1)},
                                   QStringList{"--gloss", "nan"}, QStringList{"--light-radius", "-1"},
                                   QStringList{"--accel", "embree"}, QStringList{"--zoom", "inf"}}) {
        INFO(bad.join(' ').toStdString());
        GuiOptions b;
        REQUIRE(parse(bad, b, why) == ParseResult::Error);
        REQUIRE(why.contains(bad[0]));  // the message names the flag
    }
    // One definition: the GUI's help says what the CLI's says of the cache
    REQUIRE(parse({"--help"}, o, why) == ParseResult::Help);
    REQUIRE(why.contains(QString::fromStdString(rc::cli::choices(rc::cacheRegistry()))));
}

TEST_CASE("A bad GUI flag is one line on stderr and exit 2", "[gui][cli]") {
    for (const QStringList& bad : {QStringList{"--bogus"}, QStringList{"--width", "100000"}, QStringList{"--cache", "lru"},
                                   QStringList{"--stop", "2"}, QStringList{"pair", "trio"}}) {
        INFO(bad.join(' ').toStdString());
        QProcess p;
        p.start(RAYCACHE_GUI, bad);
        REQUIRE(p.waitForFinished(60000));
        REQUIRE(p.exitCode() == 2);
        const QString err = QString::fromLocal8Bit(p.readAllStandardError());
        REQUIRE(err.startsWith("raycache-gui: "));
        REQUIRE(err.count('\n') == 1);
    }
}

TEST_CASE("With --tour, a viewer setting on the command line is refused, not dropped", "[gui][cli][tour]") {
    // Each stop sets scene, cache, size and the rest: one given beside the tour would be ignored unseen
    for (const QStringList& extra : {QStringList{"balls:4"}, QStringList{"--width", "512"},
                                     QStringList{"--cache", "none"}, QStringList{"--steps", "10"}}) {
        INFO(extra.join(' ').toStdString());
        GuiOptions o;
        QString why;
        REQUIRE(parse(QStringList{"--tour", "tours/hanrahan86.json", "--stop", "8"} + extra, o, why) ==
                ParseResult::Error);
        REQUIRE(why.startsWith("--tour: "));
        REQUIRE(why.contains(extra[0].startsWith("--") ? extra[0].mid(2) : QString("scene")));
    }
    // The window's own flags still go with a tour
    GuiOptions o;
    QString why;
    REQUIRE(parse({"--tour", "tours/hanrahan86.json", "--stop", "8", "--window", "1280x720", "--large-fonts"}, o, why) ==
            ParseResult::Ok);
    REQUIRE(o.stop == 8);
}
