#include "palette.h"

#include <algorithm>
#include <cmath>

namespace rcgui::palette {

QColor missReason(rc::MissReason r) {
    switch (r) {
        case rc::MissReason::None: return QColor(255, 255, 255);
        case rc::MissReason::Cold: return QColor(153, 153, 153);
        case rc::MissReason::Flushed: return QColor(240, 228, 66);
        case rc::MissReason::OriginChanged: return QColor(0, 114, 178);
        case rc::MissReason::TargetMissed: return QColor(213, 94, 0);
        case rc::MissReason::BlockerHit: return QColor(230, 159, 0);
        case rc::MissReason::LeftCylinder: return QColor(86, 180, 233);
        case rc::MissReason::LeftCone: return QColor(204, 121, 167);
    }
    return Qt::white;
}

QColor label(std::int64_t id, int alpha) {
    // Golden-ratio hues, alternating lightness
    const double h = std::fmod(double(id) * 0.61803398875, 1.0);
    QColor c = QColor::fromHsvF(float(h), 0.55f, (id & 1) ? 0.95f : 0.75f);
    c.setAlpha(alpha);
    return c;
}

QColor ramp(double t) {
    static const QColor stops[] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
    t = std::clamp(t, 0.0, 1.0) * 4.0;
    const int i = std::min(3, int(t));
    const double f = t - i;
    const QColor& a = stops[i];
    const QColor& b = stops[i + 1];
    return QColor(int(a.red() + f * (b.red() - a.red())), int(a.green() + f * (b.green() - a.green())),
                  int(a.blue() + f * (b.blue() - a.blue())));
}

}  // namespace rcgui::palette
