#include "view/event_text.h"

namespace rc {

std::string objectLabel(const Scene& scene, int object) {
    if (object < 0) return "nothing";
    const std::string id = "#" + std::to_string(object);
    if (object >= scene.size()) return id;
    switch (scene.objects[std::size_t(object)].shape) {
        case Shape::Sphere: return id + " sphere";
        case Shape::Polygon: return id + " polygon";
        case Shape::Cone: return id + " cone";
    }
    return id;
}

std::string decisionText(const EventRecord& r) {
    std::string d(toString(r.rayDecision()));
    if (r.missReason() != MissReason::None) (d += ": ") += toString(r.missReason());
    if (r.deferred()) d = "deferred, " + d;
    if (r.flags & EventRecord::Searched) d += " (searched)";
    return d;
}

}  // namespace rc
