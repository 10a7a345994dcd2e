#pragma once
/// \file
/// \brief Draws the overlays (cylinder of safety, blocker hull, breadth-first frontier,
/// miss markers, selection) over the image, and their legend.
#include <functional>

#include <QImage>
#include <QPainter>
#include <QStringList>

#include "analysis/beam_tree.h"
#include "legend_layout.h"
#include "overlay_options.h"
#include "view/legend.h"
#include "view/overlay_shapes.h"
#include "view/path_index.h"
#include "view/ray_focus.h"

namespace rcgui {

class Projector;

/// How much an overlay paint drew (outlines in widget pixels): a deterministic measure
/// of its cost, read by the stall probe in the tests.
struct PaintWork {
    int outlines = 0;     ///< closed outlines drawn
    int vertices = 0;     ///< their vertices
    int covering = 0;     ///< outlines that held the whole view (tinted, not stroked)
    double maxCoord = 0;  ///< largest |coordinate| of a vertex, in image units
    double length = 0;    ///< total outline length, in widget pixels
    int samples = 0;      ///< sample rays of the pixel in focus drawn (eye samples as dots)
    double sampleLength = 0;  ///< their segments' total length, in widget pixels
};

/// Paints overlays for one SessionState. Keeps a few per-pixel layers cached between
/// paints of the same state.
class OverlayPainter {
public:
    /// Paints in image coordinates (the painter maps them to the widget); `scale` is
    /// widget pixels per image pixel, so marks keep a readable size at any zoom.
    void paint(QPainter& p, const rc::SessionState& s, const Overlays& o, const rc::Selection& sel, double scale);
    /// Paints the info box, the colour key and the colour bar in widget coordinates inside
    /// `area`, beside `image` (the picture's rectangle in widget coordinates): see layOutLegend.
    void paintLegend(QPainter& p, const rc::SessionState& s, const Overlays& o, const rc::Selection& sel,
                     const QRectF& area, const QRectF& image);
    /// The heatmap shown, for its colour bar in the key, and the top of its scale (0: the
    /// state's own; see HeatmapBuilder::build).
    void setHeatmap(Heatmap h, double top = 0.0) {
        heatmap_ = h;
        heatTop_ = top;
    }
    /// The top of the heatmap scale last painted with (0: none): its colour bar, or the first render's.
    double heatmapTop() const { return lastTop_; }
    /// Lines added under the caption (a compared render: its difference in tests).
    void setExtraCaption(const QStringList& lines) { extraCaption_ = lines; }
    /// Whether the key lists the overlays' colours (the colour bar is always drawn).
    void setKeysShown(bool on) { keysShown_ = on; }
    /// Where the last key was drawn (widget coordinates; empty: none).
    const QRectF& legendKey() const { return legendKey_; }
    /// The rectangles of the last paintLegend(): the picture, the info box, key and colour bar.
    const LegendLayout& legendLayout() const { return layout_; }
    /// The font the last paintLegend() drew in (see legendFont).
    const QFont& legendDrawFont() const { return legendFont_; }
    /// The width the last caption and key wanted beside the image (widget pixels).
    double legendWidth() const { return legendWidth_; }
    /// Events a paint reads into the per-pixel layers at most (0: all): a long log is
    /// read over several paints, so that no paint stalls the window. `more` is called
    /// when a paint left events unread, to ask for the next one.
    void setEventBudget(std::size_t events, std::function<void()> more) {
        eventBudget_ = events;
        more_ = std::move(more);
    }
    /// Whether the last paint left events unread in a per-pixel layer.
    bool layersPending() const { return pending_; }

private:
    /// What the legend says: the info box's lines, the key's lines, the colour bar's title.
    struct LegendText {
        QStringList info;
        std::vector<std::pair<QColor, QString>> keys;
        bool bar = false;
        QString barTitle;
    };
    LegendText legendText(const rc::SessionState& s, const Overlays& o, const rc::Selection& sel);
    /// The boxes of `t` beside `image`, in the largest legend font that fits (sets legendFont_).
    LegendLayout layOut(const QFont& font, const QRectF& area, const QRectF& image, const LegendText& t);
    void drawInfo(QPainter& p, const LegendText& t) const;
    void drawKeys(QPainter& p, const LegendText& t) const;
    void drawBar(QPainter& p, const LegendText& t) const;
    /// The colour bar's value at fraction `t` of its scale, as labelled.
    QString barValue(double t) const;
    void paintFocus(QPainter& p, const rc::SessionState& s, const Projector& proj, const rc::RayFocus& f,
                    const Overlays& o);
    /// One shape of the core's (rc::focusShapes), in its role's colour and line.
    void paintShape(QPainter& p, const rc::OverlayShape& shape);
    void paintFrontier(QPainter& p, const rc::SessionState& s, double scale, bool markers);
    void paintMisses(QPainter& p, const rc::SessionState& s, double scale, const rc::Selection& sel);
    void paintSamples(QPainter& p, const rc::SessionState& s, const Projector& proj, const rc::RayFocus& f);

public:
    /// What the last paint() drew.
    const PaintWork& lastWork() const { return work_; }
    /// The shapes of the ray in focus the last paint() drew (rc::focusShapes).
    const std::vector<rc::OverlayShape>& drawnShapes() const { return drawn_; }
    /// The core's key entries (rc::legendEntries, rc::focusEntries) of the last paintLegend().
    const std::vector<rc::LegendEntry>& coreKeys() const { return coreKeys_; }

private:
    PaintWork work_;
    std::vector<rc::OverlayShape> drawn_;  ///< the shapes of the ray in focus the last paint() drew
    std::vector<rc::LegendEntry> coreKeys_;
    Heatmap heatmap_ = Heatmap::None;
    double heatTop_ = 0.0, lastTop_ = 0.0;
    QStringList extraCaption_;
    bool keysShown_ = true;
    QRectF legendKey_;
    double legendWidth_ = 0.0;
    double lineScale_ = 1.0;
    LegendLayout layout_;
    std::uint64_t beamSerial_ = 0;  ///< the state beams_ was built from (its serial)
    rc::BeamTreeStats beams_;       ///< the beam tree's size and coherence, for the info box
    QFont legendFont_;
    std::size_t eventBudget_ = 0;
    std::function<void()> more_;
    bool pending_ = false;
    rc::PathIndex regionsIndex_;  ///< each pixel's event at the path being filled
    int regionsCurrent_ = -1;     ///< the region tinted in regions_
    QImage regions_;
    rc::PathIndex missesIndex_;   ///< each pixel's event at the path in focus
    QImage misses_;
};

}  // namespace rcgui
