#include "stats_panel.h"

#include "render/left_out.h"

#include <QChart>
#include <QChartView>
#include <QTimer>
#include <QLabel>
#include <QLineSeries>
#include <QScrollArea>
#include <QValueAxis>
#include <QVBoxLayout>

#include "labels.h"
#include "view/session_state.h"

namespace rcgui {

StatsPanel::StatsPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    text_ = new QLabel(this);
    text_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    text_->setWordWrap(true);
    text_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
    // In a scroll area: long text (large fonts, a compared render's table) scrolls rather
    // than make the window taller than the screen
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(text_);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setMinimumHeight(80);
    layout->addWidget(scroll, 1);
    chart_ = new QChart;
    hits_ = new QLineSeries;
    hits_->setName("hits");
    hits_->setColor(QColor(0, 158, 115));
    misses_ = new QLineSeries;
    misses_->setName("misses");
    misses_->setColor(QColor(213, 94, 0));
    tests_ = new QLineSeries;
    tests_->setName("tests (right)");
    tests_->setColor(QColor(0, 114, 178));
    otherTests_ = new QLineSeries;
    otherTests_->setName("tests, compared (right)");
    QPen dashed(QColor(204, 121, 167), 2.0, Qt::DashLine);
    otherTests_->setPen(dashed);
    for (QLineSeries* s : {hits_, misses_, tests_, otherTests_}) chart_->addSeries(s);
    axisX_ = new QValueAxis;
    axisX_->setTitleText("steps");
    axisX_->setLabelFormat("%.0f");
    axisY_ = new QValueAxis;
    axisY_->setLabelFormat("%.0f");
    axisTests_ = new QValueAxis;
    axisTests_->setLabelFormat("%.0f");
    chart_->addAxis(axisX_, Qt::AlignBottom);
    chart_->addAxis(axisY_, Qt::AlignLeft);
    chart_->addAxis(axisTests_, Qt::AlignRight);
    for (QLineSeries* s : {hits_, misses_, tests_, otherTests_}) s->attachAxis(axisX_);
    otherTests_->attachAxis(axisTests_);
    otherTests_->setVisible(false);
    hits_->attachAxis(axisY_);
    misses_->attachAxis(axisY_);
    tests_->attachAxis(axisTests_);
    chart_->legend()->setAlignment(Qt::AlignBottom);
    chart_->setMargins(QMargins(2, 2, 2, 2));
    auto* view = new QChartView(chart_, this);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumHeight(200);
    layout->addWidget(view, 2);
}

void StatsPanel::showProgress(qint64 steps, double progress) {
    text_->setText(QString("running… %1 steps, %2% of the eye rays").arg(steps).arg(progress * 100.0, 0, 'f', 1));
}

namespace {
// The chart is laid out again at most this often while a render runs (the costliest part of a refresh)
constexpr qint64 kChartEveryMs = 500;
// The axes reach this much above the largest value, so that its curve does not run along the frame
constexpr double kAxisHeadroom = 1.05;
// Axis values from here on are labelled in three significant digits: seven digits and more
// do not fit beside a chart in a dock
constexpr double kLongestPlainLabel = 1e6;
}  // namespace

QString StatsPanel::summaryText() const { return text_->text(); }

QString StatsPanel::countsText(const rc::SessionState* state) {
    const rc::RenderSession& s = state->session();
    // The counts: rays, tests, searches, hits, misses
    const rc::Counters& n = s.counters();
    const double rays = std::max<double>(1.0, double(n.totalRays()));
    QString t = QString("<b>steps</b> %1 %2<br><b>rays</b> %3 (eye %4, shadow %5, reflection %6, refraction %7)<br>"
                        "<b>tests</b> %8 (%9 per ray), <b>complete searches</b> %10<br>"
                        "<b>hits</b> %11, <b>misses</b> %12, <b>deferrals</b> %13")
                    .arg(s.steps()).arg(s.done() ? "(done)" : "")
                    .arg(n.totalRays()).arg(n.rays[0]).arg(n.rays[1]).arg(n.rays[2]).arg(n.rays[3])
                    .arg(n.intersectionTests).arg(double(n.intersectionTests) / rays, 0, 'f', 2)
                    .arg(n.completeSearches).arg(n.hits).arg(n.misses).arg(n.deferrals);
    // What RayCache's caches and orders did beyond them
    QStringList reasons;
    for (int r = 1; r < rc::kMissReasons; ++r)
        if (n.missReasons[r]) reasons << QString("%1 %2").arg(text(rc::toString(rc::MissReason(r)))).arg(n.missReasons[r]);
    if (!reasons.isEmpty()) t += "<br><b>miss reasons</b> " + reasons.join(", ");
    if (n.blockerListsBuilt)
        t += QString("<br><b>blocker lists</b> %1 built, longest %2").arg(n.blockerListsBuilt).arg(n.blockerListMax);
    if (n.directionSearches)
        t += QString("<br><b>direction lists</b> %1 built, %2 misses answered from them")
                 .arg(n.directionListsBuilt).arg(n.directionSearches);
    if (n.steppedAside)
        t += QString("<br><b>stepped aside</b> %1 rays searched at once: their paths' lookups mostly searched anyway")
                 .arg(n.steppedAside);
    // The paper's measure of coherence, once the image is complete: the beam tree's size
    if (s.done()) {
        if (beamSerial_ != state->serial()) {
            beams_ = state->beams().build();
            beamSerial_ = state->serial();
        }
        t += QString("<br><b>beam tree</b> %1 beams; <b>coherence</b> %2 (average ray-tree size %3 / beam-tree size)")
                 .arg(beams_.nodes).arg(beams_.coherence, 0, 'g', 3).arg(beams_.averageRayTreeSize, 0, 'f', 2);
    }
    if (s.order().regions()) t += QString("<br><b>regions</b> %1, queue peak %2").arg(s.order().regions()).arg(s.order().queuePeak());
    // What this scene and these options leave out (no shadow rays without lights, ...)
    for (const std::string& line : rc::leftOut(s.scene(), &s.options()))
        t += QString("<br><b>left out</b> %1").arg(QString::fromStdString(line).toHtmlEscaped());
    return t;
}

QString StatsPanel::comparedText(const rc::SessionState* state, const rc::SessionState* other) {
    // A compared render: both side by side, and how many tests the second makes more
    const rc::RenderSession& s = state->session();
    const rc::Counters& n = s.counters();
    QString t;
    const rc::RenderSession& o = other->session();
    const rc::Counters& m = o.counters();
    auto name = [](const rc::RenderSession& r) {
        return QString("%1/%2").arg(text(rc::toString(r.options().cache))).arg(text(rc::toString(r.options().order)));
    };
    auto row = [](const QString& what, double a, double b) {
        const double d = b - a;
        return QString("<tr><td>%1</td><td align=right>%2</td><td align=right>%3</td><td align=right>%4%5</td></tr>")
            .arg(what).arg(a, 0, 'f', 0).arg(b, 0, 'f', 0).arg(d > 0 ? "+" : "").arg(d, 0, 'f', 0);
    };
    t += QString("<b>compared</b> at step %1%2<table cellspacing=0 cellpadding=2>"
                 "<tr><th></th><th>%3</th><th>%4</th><th>difference</th></tr>")
             .arg(o.steps()).arg(o.steps() == s.steps() ? "" : QString(" (catching up to %1)").arg(s.steps()))
             .arg(name(s), name(o));
    t += row("tests", double(n.intersectionTests), double(m.intersectionTests));
    t += row("complete searches", double(n.completeSearches), double(m.completeSearches));
    t += row("hits", double(n.hits), double(m.hits));
    t += row("misses", double(n.misses), double(m.misses));
    t += row("deferrals", double(n.deferrals), double(m.deferrals));
    t += "</table>";
    if (n.intersectionTests > 0)
        t += QString("tests: %1x the left").arg(double(m.intersectionTests) / double(n.intersectionTests), 0, 'f', 2);
    return t;
}

void StatsPanel::refresh(const rc::SessionState* state, const rc::SessionState* other) {
    if (!state) return;
    // A compared render first, so that it shows without scrolling
    const QString own = countsText(state);
    text_->setText(other ? comparedText(state, other) + "<br>" + own : own);
    // The chart at most twice a second (and whenever the render is done): relaying it out
    // is the costliest thing a refresh does
    if (throttled_ && !state->session().done() && chartClock_.isValid() && chartClock_.elapsed() < kChartEveryMs) {
        // Asks for a refresh when the half second is up, so the chart ends on the last state
        if (!chartDue_) {
            chartDue_ = true;
            QTimer::singleShot(std::max<qint64>(1, kChartEveryMs - chartClock_.elapsed()), this, [this] {
                chartDue_ = false;
                emit chartDue();
            });
        }
        return;
    }
    chartClock_.start();
    refreshChart(state, other);
}

void StatsPanel::refreshChart(const rc::SessionState* state, const rc::SessionState* other) {
    const rc::RenderSession& s = state->session();
    const rc::Counters& n = s.counters();
    // A chart a few hundred pixels wide shows no more points than that: every k-th sample
    constexpr std::size_t kPoints = 100;
    auto stride = [](std::size_t n) { return std::max<std::size_t>(1, (n + kPoints - 1) / kPoints); };
    QList<QPointF> h, m, te;
    const std::vector<rc::StatSample>& samples = state->recorder().samples();
    for (std::size_t i = 0; i < samples.size(); i += stride(samples.size())) {
        const rc::StatSample& p = samples[i];
        h << QPointF(double(p.step), double(p.hits));
        m << QPointF(double(p.step), double(p.misses));
        te << QPointF(double(p.step), double(p.tests));
    }
    h << QPointF(double(s.steps()), double(n.hits));
    m << QPointF(double(s.steps()), double(n.misses));
    te << QPointF(double(s.steps()), double(n.intersectionTests));
    // The chart's series and axes
    hits_->replace(h);
    misses_->replace(m);
    tests_->replace(te);
    double mostTests = double(n.intersectionTests);
    otherTests_->setVisible(other != nullptr);
    if (other) {
        QList<QPointF> ot;
        const std::vector<rc::StatSample>& theirs = other->recorder().samples();
        for (std::size_t i = 0; i < theirs.size(); i += stride(theirs.size()))
            ot << QPointF(double(theirs[i].step), double(theirs[i].tests));
        ot << QPointF(double(other->session().steps()), double(other->session().counters().intersectionTests));
        otherTests_->replace(ot);
        mostTests = std::max(mostTests, double(other->session().counters().intersectionTests));
    }
    axisX_->setRange(0, std::max<double>(1.0, double(s.steps())));
    axisY_->setRange(0, std::max<double>(1.0, double(std::max(n.hits, n.misses)) * kAxisHeadroom));
    axisTests_->setRange(0, std::max<double>(1.0, mostTests * kAxisHeadroom));
    // Round ticks, each label different (no "0 0 1 1 1" on small ranges)
    for (QValueAxis* a : {axisX_, axisY_, axisTests_}) {
        a->setTickCount(5);
        a->applyNiceNumbers();
        // Millions and more in three digits (2e+09, not a cut "2000000..." beside a small chart)
        a->setLabelFormat(a->max() < 8 ? "%.1f" : a->max() < kLongestPlainLabel ? "%.0f" : "%.3g");
    }
}

void StatsPanel::setLargeFonts(bool on) {
    QFont f = font();
    f.setPointSizeF(on ? 12.0 : 9.0);
    QFont title = f;
    title.setBold(true);
    for (QValueAxis* a : {axisX_, axisY_, axisTests_}) {
        a->setLabelsFont(f);
        a->setTitleFont(title);
    }
    chart_->legend()->setFont(f);
    for (QLineSeries* s : {hits_, misses_, tests_, otherTests_}) {
        QPen pen = s->pen();
        pen.setWidthF(on ? 3.5 : 2.0);
        s->setPen(pen);
    }
}

}  // namespace rcgui
