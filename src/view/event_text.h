#pragma once
/// \file
/// \brief A recorded ray and the object it hit, in the words the panels and the page show:
/// "#12 sphere", "miss: blocker_hit". RayCache's own addition.
#include <string>

#include "scene/scene.h"
#include "view/event_record.h"

namespace rc {

/// "#12 sphere", "#3 polygon", "#7 cone", or "nothing" for -1.
std::string objectLabel(const Scene& scene, int object);
/// The cache's decision on a recorded ray: "hit", "miss: blocker_hit",
/// "deferred, miss: target_missed", "uncached (searched)".
std::string decisionText(const EventRecord& r);

}  // namespace rc
