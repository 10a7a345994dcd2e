#include "view/palette.h"

#include <algorithm>

#include "view/sample_fan.h"

namespace rc {

Rgb missReasonColour(MissReason r) {
    switch (r) {
        case MissReason::None: return {255, 255, 255};
        case MissReason::Cold: return {153, 153, 153};
        case MissReason::Flushed: return {240, 228, 66};
        case MissReason::OriginChanged: return {0, 114, 178};
        case MissReason::TargetMissed: return {213, 94, 0};
        case MissReason::BlockerHit: return {230, 159, 0};
        case MissReason::LeftCylinder: return {86, 180, 233};
        case MissReason::LeftCone: return {204, 121, 167};
    }
    return {255, 255, 255};
}

Rgb fanOutcomeColour(FanOutcome o) {
    switch (o) {
        case FanOutcome::Hit: return colours::kSampleRay;
        case FanOutcome::Missed: return colours::kSampleMissed;
        case FanOutcome::Lit: return colours::kShadowLit;
        case FanOutcome::Blocked: return colours::kShadowBlocked;
    }
    return colours::kSampleRay;
}

Rgb heatRamp(double t) {
    static constexpr Rgb stops[] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
    t = std::clamp(t, 0.0, 1.0) * 4.0;
    const int i = std::min(3, int(t));
    const double f = t - i;
    const Rgb& a = stops[i];
    const Rgb& b = stops[i + 1];
    const auto mix = [f](std::uint8_t x, std::uint8_t y) { return std::uint8_t(int(x + f * (y - x))); };
    return {mix(a.r, b.r), mix(a.g, b.g), mix(a.b, b.b)};
}

RoleStyle roleStyle(ShapeRole role) {
    using namespace colours;
    switch (role) {
        case ShapeRole::Cylinder: return {kCylinder, 2.0, true, 35};
        case ShapeRole::CachedCylinder: return {kCylinder, 2.5, false, 60};
        case ShapeRole::CylinderAxis: return {kCylinder, 1.5, true, 0};
        case ShapeRole::EmptyCone: return {kHull, 2.5, true, 30};
        case ShapeRole::EmptyConeAxis: return {kHull, 0.0, false, 0, 5.7, 2};
        case ShapeRole::Hull: return {kHull, 2.5, false, 45};
        case ShapeRole::Origin: return {kOrigin, 1.5, true, 0};
        case ShapeRole::Target: return {kTarget, 3.0, false, 40};
        case ShapeRole::TargetPoint: return {kTarget, 0.0, false, 0, 8.0, 4};
        case ShapeRole::Blocker: return {kBlocker, 3.0, false, 80};
        case ShapeRole::CylinderLeft: return {kMissCause, 2.5, true, 40};
        case ShapeRole::MissedTarget: return {kMissCause, 3.5, false, 50};
        case ShapeRole::BlockerHit: return {kBlocker, 4.0, false, 120};
        case ShapeRole::Ray: return {kRay, 2.5, false, 0};
    }
    return {};
}

}  // namespace rc
