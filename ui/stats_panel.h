#pragma once
/// \file
/// \brief Dock panel: live counters and a chart of hits, misses and tests over steps.
#include <cstdint>

#include <QElapsedTimer>
#include <QWidget>

#include "analysis/beam_tree.h"

class QLabel;
class QLineSeries;
class QValueAxis;
class QChart;

namespace rcgui {

}
namespace rc { class SessionState; }
namespace rcgui {

/// The session's counters as text and a Qt Charts line chart of cumulative hits and
/// misses (left axis) and intersection tests (right axis) against steps.
class StatsPanel : public QWidget {
    Q_OBJECT
signals:
    /// A refresh came too soon after the last for the chart: refresh again.
    void chartDue();

public:
    /// Redraws the chart at most twice a second while a render runs (a live window; a
    /// screenshot draws every refresh).
    void setThrottled(bool on) { throttled_ = on; }
    explicit StatsPanel(QWidget* parent = nullptr);
    /// Axis labels, titles, legend and line widths for a projector (or back).
    void setLargeFonts(bool on);
    /// Refreshes from `state` (null: a worker is running; shows only `steps`). With a
    /// compared render `other`, adds a table of both and their difference, and its tests
    /// to the chart.
    void refresh(const rc::SessionState* state, const rc::SessionState* other = nullptr);
    /// The text shown above the chart (HTML).
    QString summaryText() const;
    /// While a worker runs: the step count it reported.
    void showProgress(qint64 steps, double progress);

private:
    /// The counts of `state`: rays, tests, searches, hits, misses, and what RayCache's
    /// caches and orders did beyond them (rich text).
    QString countsText(const rc::SessionState* state);
    /// `state` and `other` side by side, and the difference (rich text).
    QString comparedText(const rc::SessionState* state, const rc::SessionState* other);
    /// The chart of hits, misses and tests against steps (and `other`'s tests).
    void refreshChart(const rc::SessionState* state, const rc::SessionState* other);
    QElapsedTimer chartClock_;  ///< since the chart was last updated
    bool chartDue_ = false;     ///< a chartDue() is on its way
    bool throttled_ = false;
    /// The beam tree of the last complete render shown, built once per render (its serial)
    std::uint64_t beamSerial_ = 0;
    rc::BeamTreeStats beams_;
    QLabel* text_;
    QChart* chart_;
    QLineSeries *hits_, *misses_, *tests_, *otherTests_;
    QValueAxis *axisX_, *axisY_, *axisTests_;
};

}  // namespace rcgui
