#include "player.h"

#include "main_window.h"

namespace rcgui {

namespace {
// Play's ticks: about 30 a second
constexpr int kTickMs = 33;
}  // namespace

Player::Player(MainWindow& window) : QObject(&window), w_(window) {
    timer_.setInterval(kTickMs);
    connect(&timer_, &QTimer::timeout, this, &Player::onTick);
}

void Player::setPlaying(bool on) {
    credit_ = 0.0;
    if (on) timer_.start();
    else timer_.stop();
}

void Player::onTick() {
    rc::SessionState* s = w_.controller().state();
    if (!s) return;
    credit_ += w_.toolbars().raysPerSecond() * timer_.interval() / 1000.0;
    int n = int(credit_);
    credit_ -= n;
    if (n == 0) return;
    bool more = true;
    while (n-- > 0 && (more = s->step())) {}
    if (!more) w_.setPlaying(false);
    w_.refresh();
}

}  // namespace rcgui
