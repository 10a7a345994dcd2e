#pragma once
/// \file
/// \brief Short readable names of core enums and objects for the panels.
#include <QString>

#include "view/event_record.h"
#include "scene/scene.h"

namespace rcgui {

QString text(std::string_view s);
/// "#12 sphere" or "nothing".
QString objectLabel(const rc::Scene& scene, int object);
/// "hit", "miss: blocker_hit", "deferred: target_missed", "search".
QString decisionText(const rc::EventRecord& r);

}  // namespace rcgui
