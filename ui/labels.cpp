#include "labels.h"

namespace rcgui {

QString text(std::string_view s) { return QString::fromUtf8(s.data(), qsizetype(s.size())); }

QString objectLabel(const rc::Scene& scene, int object) {
    if (object < 0) return "nothing";
    if (object >= scene.size()) return QString("#%1").arg(object);
    return QString("#%1 %2").arg(object).arg(scene.objects[object].shape == rc::Shape::Sphere ? "sphere" : "polygon");
}

QString decisionText(const rc::EventRecord& r) {
    QString d = text(rc::toString(r.rayDecision()));
    if (r.missReason() != rc::MissReason::None) d += ": " + text(rc::toString(r.missReason()));
    if (r.deferred()) d = "deferred, " + d;
    if (r.flags & rc::EventRecord::Searched) d += " (searched)";
    return d;
}

}  // namespace rcgui
