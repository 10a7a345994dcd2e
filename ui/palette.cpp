#include "palette.h"

#include <algorithm>
#include <cmath>

namespace rcgui::palette {

QColor missReason(rc::MissReason r) { return qt(rc::missReasonColour(r)); }

QColor label(std::int64_t id, int alpha) {
    // Golden-ratio hues, alternating lightness
    const double h = std::fmod(double(id) * 0.61803398875, 1.0);
    QColor c = QColor::fromHsvF(float(h), 0.55f, (id & 1) ? 0.95f : 0.75f);
    c.setAlpha(alpha);
    return c;
}

QColor ramp(double t) { return qt(rc::heatRamp(t)); }

QColor fanOutcome(rc::FanOutcome o) { return qt(rc::fanOutcomeColour(o)); }

}  // namespace rcgui::palette
