#pragma once
/// \file
/// \brief Headless mode: build the window, trace N rays, write the window to a PNG.
#include <vector>

#include <QTextStream>

#include "gui_options.h"

namespace rcgui {

class MainWindow;

/// Applies the command line's choices to a window: scene, cache, order, size, the
/// first `steps` rays, overlays, heatmap, selection. Errors go to `err`; returns false
/// on a bad scene (the caller exits with status 2).
bool applyOptions(MainWindow& w, const GuiOptions& o, QTextStream& err);

/// Renders `o.screenshot` and returns the process exit status: 0 when written, 2 for a
/// bad scene, 1 when the PNG cannot be written. With a tour (its stops' options read by
/// stopOptions()), the window shows its stop `o.stop`, strip and caption.
int renderScreenshot(const GuiOptions& o, QTextStream& out, QTextStream& err, const rc::Tour* tour = nullptr,
                     const std::vector<GuiOptions>& stops = {});

/// At most this many frames are recorded.
inline constexpr int kMaxRecordedFrames = 10000;

/// Records the fill as numbered PNGs (`o.record`/frame_00000.png, ...), one every
/// `o.every` steps until the image is done, with the chosen overlays. Returns the exit
/// status: 0, 1 when a file cannot be written, 2 for a bad scene.
int recordSequence(const GuiOptions& o, QTextStream& out, QTextStream& err);

}  // namespace rcgui
