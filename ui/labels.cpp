#include "labels.h"

#include "view/event_text.h"

namespace rcgui {

QString text(std::string_view s) { return QString::fromUtf8(s.data(), qsizetype(s.size())); }

QString objectLabel(const rc::Scene& scene, int object) { return text(rc::objectLabel(scene, object)); }

QString decisionText(const rc::EventRecord& r) { return text(rc::decisionText(r)); }

}  // namespace rcgui
