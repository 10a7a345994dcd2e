#pragma once
/// \file
/// \brief Short readable names of core enums and objects for the panels.
#include <QString>

#include "view/event_record.h"
#include "scene/scene.h"

namespace rcgui {

QString text(std::string_view s);
/// "#12 sphere" or "nothing" (rc::objectLabel).
QString objectLabel(const rc::Scene& scene, int object);
/// "hit", "miss: blocker_hit", "deferred, miss: target_missed" (rc::decisionText).
QString decisionText(const rc::EventRecord& r);

}  // namespace rcgui
