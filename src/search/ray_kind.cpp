#include "search/ray_kind.h"

namespace rc {

std::string_view toString(RayKind k) {
    switch (k) {
        case RayKind::Primary: return "primary";
        case RayKind::Shadow: return "shadow";
        case RayKind::Reflection: return "reflection";
        case RayKind::Refraction: return "refraction";
    }
    return "?";
}

}  // namespace rc
