#include "view/overlay_layers.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "search/blocker_lists.h"
#include "view/miss_cause.h"

namespace rc {

std::vector<std::uint8_t> missLayer(const PathIndex& index) {
    std::vector<std::uint8_t> out(index.pixels());
    for (std::size_t px = 0; px < out.size(); ++px) out[px] = missMark(index, int(px));
    return out;
}

namespace {
/// Calls `f(pixel, event)` for each committed event at ray-tree path `node`, oldest first:
/// the last call for a pixel is its event at the path (as PathIndex keeps it), without
/// PathIndex's entry of every pixel (a page redrawing an image of millions of pixels).
template <class F>
void eachAtPath(const TraceRecorder& rec, int node, F&& f) {
    for (const EventRecord e : rec.events())
        if (e.node == node && !e.deferred()) f(std::size_t(e.pixel), e);
}
}  // namespace

std::vector<std::uint8_t> missLayer(const SessionState& s, int path) {
    std::vector<std::uint8_t> out(std::size_t(s.width()) * std::size_t(s.height()), 0);
    // What missMark() reads of a PathIndex entry
    eachAtPath(s.recorder(), path, [&](std::size_t px, const EventRecord& e) {
        out[px] = e.rayDecision() == Decision::Miss ? e.reason : 0;
    });
    return out;
}

namespace {
/// The region marks of a picture of `width` x `height` pixels whose pixel at (x, y) lies
/// in region `regionAt(x, y)` (-1: none yet) while region `current` is being filled.
template <class RegionAt>
std::vector<std::uint8_t> regionMarks(int width, int height, int current, RegionAt&& regionAt) {
    const int w = width, h = height;
    std::vector<std::uint8_t> out(std::size_t(w) * std::size_t(h), 0);
    const auto at = [&](int x, int y) { return x < 0 || y < 0 || x >= w || y >= h ? -1 : regionAt(x, y); };
    // One pass over the pixels, each compared with its right and lower neighbours
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int r = at(x, y);
            if (r < 0) continue;
            auto& mark = out[std::size_t(y) * std::size_t(w) + std::size_t(x)];
            if (r == current) mark = std::uint8_t(RegionMark::Current);
            else if (at(x + 1, y) != r || at(x, y + 1) != r) mark = std::uint8_t(RegionMark::Edge);
        }
    return out;
}
}  // namespace

std::vector<std::uint8_t> regionLayer(const PathIndex& index, int width, int height, int current) {
    return regionMarks(width, height, current, [&](int x, int y) {
        const PathIndex::Entry& e = index.at(y * width + x);
        return e.event < 0 ? -1 : int(e.region);
    });
}

std::vector<std::uint8_t> regionLayer(const SessionState& s) {
    const FrontierView f = s.session().order().frontier();
    const int w = s.width();
    if (f.path < 0) return std::vector<std::uint8_t>(std::size_t(w) * std::size_t(s.height()), 0);
    // Each pixel's region at the path only (what regionMarks reads of a PathIndex entry)
    std::vector<std::int32_t> region(std::size_t(w) * std::size_t(s.height()), -1);
    eachAtPath(s.recorder(), f.path, [&](std::size_t px, const EventRecord& e) { region[px] = e.region; });
    return regionMarks(w, s.height(), f.region, [&](int x, int y) { return int(region[std::size_t(y) * std::size_t(w) + std::size_t(x)]); });
}

std::vector<std::string> focusCaption(const SessionState& s, const Selection& sel) {
    std::vector<std::string> lines;
    const RenderSession& session = s.session();
    lines.push_back(s.scene().name + "  " + std::string(toString(session.strategy().kind())) + "/" +
                    std::string(toString(session.order().kind())) + "  " + std::to_string(s.width()) + "x" +
                    std::to_string(s.height()) + "  step " + std::to_string(session.steps()));
    if (const auto focus = RayFocus::of(s, sel)) {
        const RayFocus& f = *focus;
        std::string d(toString(f.decision));
        if (f.reason != MissReason::None) d += " (" + std::string(toString(f.reason)) + ")";
        if (f.deferred) d = "deferred: " + d;
        const std::string hit = f.deferred ? "?" : f.hit >= 0 ? "#" + std::to_string(f.hit) : "nothing";
        lines.push_back(std::string(f.selected ? "selected:" : "ray:") + " pixel (" + std::to_string(f.pixel % s.width()) +
                        "," + std::to_string(f.pixel / s.width()) + ")  " + session.cacheTree().label(f.node) + "  hit " +
                        hit + "  " + d + "  " + std::to_string(f.tests) + " tests");
    } else if (sel.pixel >= 0) {
        lines.push_back("selected pixel (" + std::to_string(sel.pixel % s.width()) + "," +
                        std::to_string(sel.pixel / s.width()) + "): not traced yet");
    }
    return lines;
}

std::string missCauseText(const SessionState& s, const RayFocus& f) {
    const MissCause c = missCauseOf(s, f);
    // A shadow ray's entry holds its light, not an object; lights count from 1, as paths
    // name them ("shadow 1")
    const std::string was = c.cachedObject >= 0              ? "#" + std::to_string(c.cachedObject)
                            : f.kind == RayKind::Shadow && f.light >= 0 ? "light " + std::to_string(f.light + 1)
                                                                        : "nothing";
    if (c.reason == MissReason::TargetMissed) return "miss: the cached target " + was + " is not hit";
    if (c.reason == MissReason::BlockerHit)
        return "miss: blocker #" + std::to_string(c.blocker) + " is hit before the cached " + was;
    if (c.reason == MissReason::LeftCylinder && c.cylinder.radius > 0.0) {
        char r[32];
        std::snprintf(r, sizeof r, "%.3g", c.cylinder.radius);
        return "miss: the ray leaves the cached cylinder (r " + std::string(r) + ", cached " + was + ")";
    }
    if (c.valid()) return "miss (" + std::string(toString(c.reason)) + "); the entry held " + was;
    return {};
}

int eventAtPath(const SessionState& s, int pixel, const std::string& path, std::string& error) {
    // Paths are compared without spaces and case: "eye/reflection/shadow1" names "shadow 1"
    auto norm = [](std::string t) {
        t.erase(std::remove(t.begin(), t.end(), ' '), t.end());
        for (char& c : t) c = char(std::tolower(static_cast<unsigned char>(c)));
        return t;
    };
    const CacheTree& tree = s.session().cacheTree();
    std::vector<std::string> have;
    int found = -1;
    for (int i : s.recorder().eventsOf(pixel)) {
        const EventRecord& r = s.recorder().events()[std::size_t(i)];
        const std::string label = tree.label(r.node);
        if (std::find(have.begin(), have.end(), label) == have.end()) have.push_back(label);
        if (norm(label) == norm(path) && (found < 0 || !r.deferred())) found = i;
    }
    if (found >= 0) return found;
    std::string list;
    for (const std::string& h : have) list += (list.empty() ? "" : ", ") + h;
    error = "pixel (" + std::to_string(pixel % s.width()) + "," + std::to_string(pixel / s.width()) +
            ") has no ray at path '" + path + "'; its rays: " + (list.empty() ? "none yet" : list);
    return -1;
}

int showcaseEvent(const SessionState& s) {
    const BlockerLists* lists = s.session().strategy().blockerLists();
    const auto& events = s.recorder().events();
    int best = -1;
    for (const bool reflected : {true, false}) {
        best = int(events.findBackward(events.size(), [&](std::size_t, const EventRecord& r) {
            if (r.deferred() || r.hit < 0) return false;
            if (reflected != (r.rayKind() == RayKind::Reflection) || (!reflected && r.node != 0)) return false;
            if (!lists) return true;
            const int origin = r.origin >= 0 ? r.origin : lists->eyeSite();
            const std::vector<int>* l = lists->find(origin, r.hit);
            return l && !l->empty();
        }));
        if (best >= 0) return best;
    }
    return int(events.findBackward(events.size(),
                                   [](std::size_t, const EventRecord& r) { return !r.deferred() && r.hit >= 0; }));
}

}  // namespace rc
