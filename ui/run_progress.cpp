#include "run_progress.h"

#include <cmath>

#include <QMainWindow>
#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>

namespace rcgui {

namespace {
// The bar's steps (tenths of a percent), and its width in the status bar
constexpr int kProgressSteps = 1000, kProgressWidth = 260;
// How long "run finished" stays in the status bar
constexpr int kEndMessageMs = 5000;
}  // namespace

RunProgress::RunProgress(QMainWindow& window) : QObject(&window), window_(window) {
    bar_ = new QProgressBar(&window);
    bar_->setRange(0, kProgressSteps);
    bar_->setMaximumWidth(kProgressWidth);
    bar_->setFormat("%p% of the eye rays");
    cancel_ = new QPushButton("Cancel", &window);
    cancel_->setToolTip("Stop the run (Escape); what is traced so far stays");
    connect(cancel_, &QPushButton::clicked, this, &RunProgress::cancelClicked);
    window.statusBar()->addPermanentWidget(bar_);
    window.statusBar()->addPermanentWidget(cancel_);
    bar_->hide();
    cancel_->hide();
}

void RunProgress::setBusy(bool busy) {
    bar_->setVisible(busy);
    cancel_->setVisible(busy);
    if (busy) bar_->setValue(0);
}

void RunProgress::show(qint64 steps, double progress) {
    bar_->setValue(int(std::lround(kProgressSteps * progress)));
    window_.statusBar()->showMessage(QString("running… %1 steps").arg(steps));
}

void RunProgress::ended(bool completed) {
    window_.statusBar()->showMessage(completed ? "run finished" : "run cancelled", kEndMessageMs);
}

}  // namespace rcgui
