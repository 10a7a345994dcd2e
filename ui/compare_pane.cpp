#include "compare_pane.h"

#include <QComboBox>
#include <QSplitter>

#include "heatmap_builder.h"
#include "image_view.h"
#include "main_window.h"
#include "panels.h"
#include "scene_view.h"
#include "stats_panel.h"
#include "tour_player.h"
#include "view/compare_caption.h"

namespace rcgui {

ComparePane::ComparePane(MainWindow& window) : QObject(&window), w_(window) {
    view_ = new ImageView(&window);
    view_->hide();
    painter_.setKeysShown(false);
    hookView();
    // The two views zoom and pan together: the same pixels side by side
    follow(w_.view_, view_);
    follow(view_, w_.view_);
    connect(&controller_, &SessionController::changed, this, &ComparePane::refresh);
    connect(&controller_, &SessionController::snapshot, this, [this](const QImage& img, qint64, double) {
        if (w_.heatmap_ == Heatmap::None) view_->setImage(img);
    });
    connect(&controller_, &SessionController::failed, this, [this](const QString& why) {
        w_.reportError("Cannot start the compared render", why);
    });
}

ComparePane::~ComparePane() { stop(); }

void ComparePane::stop() {
    controller_.cancel();
    controller_.wait();
}

void ComparePane::hookView() {
    // The same overlays, the selection carried over by pixel and path
    view_->setOverlayHook([this](QPainter& p, double scale) {
        if (const rc::SessionState* c = controller_.state(); c && choice_)
            painter_.paint(p, *c, w_.overlays_, selection(), scale);
    });
    view_->setLegendHook([this](QPainter& p, const QRectF& area) {
        if (const rc::SessionState* c = controller_.state(); c && choice_) {
            painter_.paintLegend(p, *c, w_.overlays_, selection(), area, view_->shownImageRect());
            keepLegendBeside(view_, painter_);
        }
    });
    view_->setTooltipHook([this](int x, int y) { return pixelTooltip(controller_.state(), x, y); });
    connect(view_, &ImageView::pixelClicked, &w_, &MainWindow::selectPixel);
    connect(view_, &ImageView::cleared, &w_, [this] { w_.selectPixel(-1, -1); });
}

void ComparePane::follow(ImageView* from, ImageView* to) {
    connect(from, &ImageView::viewMoved, this, [this, from, to] {
        if (!choice_ || following_ || to->isHidden() || from->image().size() != to->image().size()) return;
        following_ = true;
        // The same image point at the same place relative to each view's centre
        const QPointF shift = QPointF(to->width() - from->width(), to->height() - from->height()) / 2.0;
        to->setZoom(from->zoom(), from->pan() + shift);
        following_ = false;
    });
}

rc::Selection ComparePane::selection() const {
    // The same pixel; the chosen ray carried over by its pixel and path
    rc::Selection sel = w_.selection_;
    sel.event = -1;
    const rc::SessionState* s = w_.controller_.state();
    const rc::SessionState* c = controller_.state();
    if (!c || sel.pixel >= c->width() * c->height()) return {};
    if (s && w_.selection_.event >= 0 && std::size_t(w_.selection_.event) < s->recorder().events().size()) {
        const rc::EventRecord& r = s->recorder().events()[std::size_t(w_.selection_.event)];
        sel.event = c->recorder().eventAt(r.pixel, r.node);
        if (sel.event < 0) sel.pixel = r.pixel;
    }
    return sel;
}

double ComparePane::heatmapTop() const {
    // Two renders side by side share one scale: the larger of their own
    const Heatmap h = w_.heatmap_;
    if (!choice_ || (h != Heatmap::Tests && h != Heatmap::VisitOrder)) return 0.0;
    const rc::SessionState* s = w_.controller_.state();
    const rc::SessionState* c = controller_.state();
    if (!s || !c) return 0.0;
    return std::max(HeatmapBuilder::scaleOf(*s, h), HeatmapBuilder::scaleOf(*c, h));
}

void ComparePane::showChoice() {
    if (!box_) return;
    const QSignalBlocker b(box_);
    const int i = choice_ ? box_->findData(toString(*choice_)) : 0;
    box_->setCurrentIndex(std::max(0, i));
}

void ComparePane::choose(const std::optional<CompareChoice>& choice) {
    choice_ = choice;
    view_->setVisible(choice.has_value());
    if (!choice) {
        controller_.clear();
        painter_.setExtraCaption({});
    }
    showChoice();
}

bool ComparePane::set(const QString& spec, QString& error) {
    const QString t = spec.trimmed().toLower();
    if (t.isEmpty() || t == "off") {
        choose(std::nullopt);
        w_.refresh();
        return true;
    }
    const auto choice = parseCompare(spec, error);
    if (!choice) {
        showChoice();  // keeps what was there
        return false;
    }
    choice_ = choice;
    view_->show();
    showChoice();
    start();
    return true;
}

void ComparePane::start() {
    if (!choice_ || !w_.scene_) return;
    rc::RenderOptions o = w_.effectiveOptions();
    o.cache = choice_->cache;
    o.order = choice_->order;
    if (auto ready = w_.reuseOnReset_ ? w_.tour_->takeAhead({w_.scene_, o}) : nullptr) {
        controller_.adopt(std::move(ready));
    } else if (w_.workerSessions_) {
        controller_.resetOnWorker({w_.scene_, o});
        ++w_.rendersBuilt_;
    } else {
        try {
            controller_.reset({w_.scene_, o});
            ++w_.rendersBuilt_;
        } catch (const std::exception& e) {
            w_.reportError("Cannot start the compared render", QString::fromUtf8(e.what()));
        }
    }
    w_.split_->setSizes(paneSizes(true, !w_.sceneView_->isHidden()));
    view_->fit();
}

// [compare-sync]
void ComparePane::sync(bool now) {
    if (!choice_) return;
    const rc::SessionState* s = w_.controller_.state();
    if (!s) return;  // the first render is running: catch up when it hands its state back
    if (now && controller_.busy()) controller_.wait();
    rc::SessionState* c = controller_.state();
    if (!c) return;  // the compared render is catching up on its worker
    const std::int64_t want = s->session().steps(), have = c->session().steps();
    if (want == have) {
        // Every render has the same rays: when the first is done, so is the second
        if (s->session().done() && !c->session().done()) c->step();
        return;
    }
    // A short way forwards (a step, a play tick) on this thread; else on the worker,
    // rebuilding and replaying when it lies behind
    constexpr std::int64_t kOnThisThread = 2000;
    if (want > have && (now || want - have <= kOnThisThread)) {
        c->runUntil(rc::RunGoal::ToStep, want);
        return;
    }
    controller_.goToStep(want);
    if (now) controller_.wait();
}
// [compare-sync]

void ComparePane::refresh() {
    if (!choice_) return;
    sync(false);
    const rc::SessionState* c = controller_.state();
    const rc::SessionState* s = w_.controller_.state();
    if (!c) return;
    const double top = heatmapTop();
    int path = 0;
    if (const auto& e = c->recorder().lastCommitted()) path = e->task.node;
    view_->setImage(HeatmapBuilder::build(*c, w_.heatmap_, path, top));
    painter_.setHeatmap(w_.heatmap_, top);
    w_.overlayPainter_.setHeatmap(w_.heatmap_, top);
    QStringList extra;
    if (s) {
        // The core's lines (rc::compareCaption), as the page's
        for (const std::string& line : rc::compareCaption(*s, *c)) extra << QString::fromStdString(line);
        w_.statsPanel()->refresh(s, c);
    }
    painter_.setExtraCaption(extra);
    view_->update();
    w_.view_->update();
}

}  // namespace rcgui
