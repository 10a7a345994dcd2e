#pragma once
/// \file
/// \brief The overlays, registered once: each one's name, the other names it answers to (a
/// tour's `overlays=` and the GUI's `--overlays` take either) and one line that describes it.
/// The GUI's toggles, the page's checkboxes and the tours read this list. RayCache's own
/// addition.
#include <string>
#include <string_view>
#include <vector>

#include "scene/registry.h"

namespace rc {

/// One overlay as the registry holds it.
struct OverlayInfo {
    std::string name;                  ///< e.g. "hull"
    std::string description;           ///< one line
    std::vector<std::string> aliases;  ///< other names, e.g. "cone" and "blocker" for "hull"
    bool inPage = true;                ///< the web page draws it too
};

/// Every overlay, in the order the GUI's menu lists them.
const Registry<OverlayInfo>& overlayRegistry();

/// The name of the overlay `word` names (its name or an alias; any case), or "" when none
/// does. "all" and "none" name no one overlay.
std::string overlayNamed(std::string_view word);

}  // namespace rc
