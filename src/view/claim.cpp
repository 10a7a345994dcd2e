#include "view/claim.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <regex>

#include "search/cache_tree.h"
#include "view/overlay_layers.h"
#include "view/overlay_registry.h"
#include "view/viewer_settings.h"

namespace rc {

const std::vector<ClaimQuantity>& claimQuantities() {
    static const std::vector<ClaimQuantity> all = {
        {"misses", "pixels the Misses overlay marks: committed misses at the path of the ray in focus", "misses"},
        {"path", "the ray-tree path of the ray in focus (eye, eye/reflection, ...)", ""},
        {"decision", "the cache's decision for the ray in focus (uncached, hit, miss)", ""},
        {"reason", "the reason of the focused ray's miss (cold, flushed, left_cylinder, ...; none)", ""},
        {"tests", "the ray-object tests of the ray in focus", ""},
        {"hits_object", "1 when the ray in focus hit an object, else 0", ""},
        {"blockers", "the potential blockers the focused ray's hull lists", "cone"},
        {"cylinder_radius", "the radius of the cylinder of safety drawn for the ray in focus", "cylinder"},
        {"hit_radius", "the radius of the bounding sphere of the object the ray in focus hit", "cylinder"},
        {"shadow_rays", "shadow rays in the ray tree of the pixel in focus", "panel:ray-tree"},
        {"reflections", "reflection rays in the ray tree of the pixel in focus", "panel:ray-tree"},
        {"flushed_entries", "entries of the cache tree marked flushed", "panel:cache-tree"},
        {"cache_paths", "paths (entries) of the cache tree", "panel:cache-tree"},
        {"total_tests", "ray-object tests of the whole render (what the tests heatmap sums; the compare caption's tests)",
         "heatmap:tests", true},
        {"beams", "the size of the beam tree of the render (its beams)", "panel:statistics"},
        {"coherence", "the paper's coherence: average ray-tree size / beam-tree size", "panel:statistics"},
        {"inside", "1 when the ray in focus leaves its object into its interior, else 0", ""},
        {"hit_is_origin", "1 when the ray in focus hits the object it leaves, else 0", ""},
        {"queued", "pixels the Frontier overlay marks as waiting in the fill queue", "frontier"},
        {"traced_pixels", "pixels whose eye ray has been traced (drawn in the picture)", ""},
        {"pixels", "pixels of the picture", ""},
        {"all_misses", "committed cache misses of the render (the Statistics panel's misses; the compare caption's)",
         "panel:statistics", true},
        {"misses_cold", "the render's misses of reason cold (Statistics: miss reasons)", "panel:statistics"},
        {"misses_flushed", "... of reason flushed", "panel:statistics"},
        {"misses_origin_changed", "... of reason origin_changed", "panel:statistics"},
        {"misses_target_missed", "... of reason target_missed", "panel:statistics"},
        {"misses_blocker_hit", "... of reason blocker_hit", "panel:statistics"},
        {"misses_left_cylinder", "... of reason left_cylinder", "panel:statistics"},
        {"misses_left_cone", "... of reason left_cone", "panel:statistics"},
        {"objects", "objects in the scene", ""},
        {"spheres", "spheres in the scene", ""},
        {"lights", "lights in the scene", ""},
        {"steps", "rays traced so far", ""},
        {"complete", "1 when the image is complete, else 0", ""},
    };
    return all;
}

namespace {

const ClaimQuantity* findQuantity(const std::string& name) {
    for (const ClaimQuantity& q : claimQuantities())
        if (name == q.name) return &q;
    return nullptr;
}

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    if (b == std::string::npos) return {};
    return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::optional<double> numberOf(const std::string& s) {
    if (s.empty()) return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

bool parseSide(const std::string& raw, Claim::Side& side, std::string& error) {
    std::string s = trim(raw);
    if (s.empty()) {
        error = "a side of the comparison is empty";
        return false;
    }
    if (const auto n = numberOf(s)) {
        side.number = n;
        return true;
    }
    if (const auto star = s.find('*'); star != std::string::npos) {
        const auto f = numberOf(trim(s.substr(0, star)));
        if (!f) {
            error = "'" + s + "': a factor must be a number before '*'";
            return false;
        }
        side.factor = *f;
        s = trim(s.substr(star + 1));
    }
    std::string pane = "left";
    if (s.rfind("left.", 0) == 0 || s.rfind("right.", 0) == 0) {
        pane = s.substr(0, s.find('.'));
        s = s.substr(pane.size() + 1);
    }
    if (findQuantity(s)) {
        side.pane = pane;
        side.quantity = s;
        return true;
    }
    if (side.factor != 1.0 || pane != "left" || raw.find('.') != std::string::npos ||
        !std::all_of(s.begin(), s.end(), [](unsigned char c) {
            return std::islower(c) || std::isdigit(c) || c == '_' || c == '/' || c == ' ';
        })) {
        std::string names;
        for (const ClaimQuantity& q : claimQuantities()) names += (names.empty() ? "" : ", ") + std::string(q.name);
        error = "unknown quantity '" + s + "' (a claim reads " + names + ")";
        return false;
    }
    side.word = s;  // a name to compare with: a miss reason, a path, a decision
    return true;
}

bool compare(double a, const std::string& op, double b) {
    if (op == "<") return a < b;
    if (op == "<=") return a <= b;
    if (op == ">") return a > b;
    if (op == ">=") return a >= b;
    if (op == "==") return a == b;
    return a != b;
}

}  // namespace

std::optional<Claim> parseClaim(const std::string& text, std::string& error) {
    Claim c;
    c.text = text;
    static const std::regex op(R"((<=|>=|==|!=|<|>))");
    std::smatch m;
    if (!std::regex_search(text, m, op)) {
        error = "'" + text + "': a claim compares two sides with <, <=, ==, !=, >= or >";
        return std::nullopt;
    }
    c.op = m.str(1);
    const std::string rest = m.suffix().str();
    if (std::regex_search(rest, op)) {
        error = "'" + text + "': a claim makes one comparison";
        return std::nullopt;
    }
    std::string why;
    if (!parseSide(m.prefix().str(), c.lhs, why) || !parseSide(rest, c.rhs, why)) {
        error = "'" + text + "': " + why;
        return std::nullopt;
    }
    if (c.lhs.quantity.empty() && c.rhs.quantity.empty()) {
        error = "'" + text + "': a claim reads at least one quantity from the picture";
        return std::nullopt;
    }
    const bool words = !c.lhs.word.empty() || !c.rhs.word.empty();
    if (words && c.op != "==" && c.op != "!=") {
        error = "'" + text + "': names compare only with == or !=";
        return std::nullopt;
    }
    return c;
}

std::string claimNotDrawn(const Claim& claim, bool compared, const std::vector<std::string>& overlays,
                          const std::string& heatmap, const std::vector<std::string>& panels) {
    for (const Claim::Side* side : {&claim.lhs, &claim.rhs}) {
        if (side->quantity.empty()) continue;
        if (side->pane == "right" && !compared) return "'" + claim.text + "' reads the right pane of a stop without 'compare'";
        const ClaimQuantity& q = *findQuantity(side->quantity);
        const std::string drawn = q.drawnBy;
        if (drawn.empty() || (compared && q.compareCaption)) continue;
        const auto has = [](const std::vector<std::string>& list, const std::string& w) {
            return std::find(list.begin(), list.end(), w) != list.end();
        };
        if (drawn.rfind("panel:", 0) == 0) {
            if (!has(panels, drawn.substr(6)))
                return "'" + claim.text + "' reads " + side->quantity + ", which the " + drawn.substr(6) +
                       " panel shows: the stop does not show it";
        } else if (drawn.rfind("heatmap:", 0) == 0) {
            if (heatmap != drawn.substr(8))
                return "'" + claim.text + "' reads " + side->quantity + ", which the " + drawn.substr(8) +
                       " heatmap shows: the stop does not show it";
        } else if (!has(overlays, drawn) && !has(overlays, overlayNamed(drawn)) && !has(overlays, "all")) {
            return "'" + claim.text + "' reads " + side->quantity + ", which the " + drawn +
                   " overlay draws: the stop does not draw it";
        }
    }
    return {};
}

ClaimView claimViewOf(const TourStop& stop) {
    // Read as the viewers read the stop (rc::shownSettings): registered overlay names, "all"
    // expanded, no heatmap as ""
    const ViewerSettings shown = shownSettings(stop);
    ClaimView v;
    v.overlays = shown.overlays.value_or(std::vector<std::string>{});
    v.heatmap = shown.heatmap;
    v.panels = shown.panels.value_or(std::vector<std::string>{});
    return v;
}

std::string parseStopClaims(const TourStop& stop, std::vector<Claim>& out) {
    const ClaimView v = claimViewOf(stop);
    const bool compared = !stop.value("compare").empty() && stop.value("compare") != "off";
    for (const std::string& text : stop.claims) {
        std::string error;
        const auto c = parseClaim(text, error);
        if (!c) return error;
        if (std::string why = claimNotDrawn(*c, compared, v.overlays, v.heatmap, v.panels); !why.empty()) return why;
        out.push_back(*c);
    }
    return {};
}

std::string ClaimValue::shown() const {
    if (!number) return word;
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", *number);
    return buf;
}

std::string focusPath(const ClaimPane& pane) {
    const auto f = RayFocus::of(*pane.state, pane.selection);
    return f ? pane.state->session().cacheTree().label(f->node) : std::string();
}

std::optional<ClaimValue> readQuantity(const ClaimPane& pane, const std::string& name, std::string& error) {
    const SessionState& s = *pane.state;
    const RenderSession& session = s.session();
    auto number = [](double v) { return ClaimValue{v, {}}; };
    // Of the render as a whole
    if (name == "objects") return number(s.scene().size());
    if (name == "lights") return number(double(s.scene().lights.size()));
    if (name == "steps") return number(double(session.steps()));
    if (name == "complete") return number(session.done() ? 1 : 0);
    if (name == "spheres")
        return number(double(std::count_if(s.scene().objects.begin(), s.scene().objects.end(),
                                           [](const Object& o) { return o.shape == Shape::Sphere; })));
    if (name == "pixels") return number(double(s.width()) * s.height());
    if (name == "traced_pixels") {
        int n = 0;
        for (int px = 0; px < s.width() * s.height(); ++px) n += s.recorder().visited(px) ? 1 : 0;
        return number(n);
    }
    if (name == "queued") return number(double(session.order().frontier().queued.size()));
    if (name == "all_misses") return number(double(session.counters().misses));
    if (name.rfind("misses_", 0) == 0) {
        for (int r = 1; r < kMissReasons; ++r)
            if (name.substr(7) == toString(MissReason(r))) return number(double(session.counters().missReasons[std::size_t(r)]));
    }
    if (name == "total_tests") return number(double(session.counters().intersectionTests));
    if (name == "beams" || name == "coherence") {
        const BeamTreeStats b = s.beams().build();
        return number(name == "beams" ? double(b.nodes) : b.coherence);
    }
    if (name == "cache_paths" || name == "flushed_entries") {
        const CacheTree& tree = session.cacheTree();
        if (name == "cache_paths") return number(tree.size());
        int flushed = 0;
        for (int i = 0; i < tree.size(); ++i) flushed += tree.entry(i).state == CacheEntry::State::Flushed ? 1 : 0;
        return number(flushed);
    }
    // Of the ray in focus
    const auto focus = RayFocus::of(s, pane.selection);
    if (!focus) {
        error = "no ray is in focus";
        return std::nullopt;
    }
    const RayFocus& f = *focus;
    if (name == "misses") {
        const std::vector<std::uint8_t> layer = missLayer(s, f.node);
        return number(double(std::count_if(layer.begin(), layer.end(), [](std::uint8_t m) { return m != 0; })));
    }
    if (name == "path") return ClaimValue{std::nullopt, session.cacheTree().label(f.node)};
    if (name == "decision") return ClaimValue{std::nullopt, std::string(toString(f.decision))};
    if (name == "reason") return ClaimValue{std::nullopt, f.decision == Decision::Miss ? std::string(toString(f.reason)) : "none"};
    if (name == "tests") return number(f.tests);
    if (name == "inside") return number(f.origin.inside ? 1 : 0);
    if (name == "hit_is_origin") return number(f.hit >= 0 && f.hit == f.origin.object ? 1 : 0);
    if (name == "hits_object") return number(f.hit >= 0 ? 1 : 0);
    if (name == "blockers") return number(double(hullOf(s, f).listed));
    if (name == "cylinder_radius") return number(cylinderOf(s, f).cylinder.radius);
    if (name == "hit_radius") {
        if (f.hit < 0) {
            error = "the ray in focus hit nothing";
            return std::nullopt;
        }
        return number(s.scene().objects[std::size_t(f.hit)].bound.r);
    }
    if (name == "shadow_rays" || name == "reflections") {
        const RayKind kind = name == "shadow_rays" ? RayKind::Shadow : RayKind::Reflection;
        int n = 0;
        for (int e : s.recorder().eventsOf(f.pixel)) {
            const EventRecord& r = s.recorder().events()[std::size_t(e)];
            n += !r.deferred() && r.rayKind() == kind ? 1 : 0;
        }
        return number(n);
    }
    error = "unknown quantity '" + name + "'";
    return std::nullopt;
}

ClaimResult checkClaim(const Claim& claim, const ClaimView& view) {
    ClaimResult out;
    out.text = claim.text;
    std::optional<ClaimValue> value[2];
    std::string shown[2];
    const Claim::Side* sides[2] = {&claim.lhs, &claim.rhs};
    for (int i = 0; i < 2; ++i) {
        const Claim::Side& side = *sides[i];
        if (side.quantity.empty()) {
            value[i] = ClaimValue{side.number, side.word};
            shown[i] = value[i]->shown();
            continue;
        }
        const std::size_t pane = side.pane == "right" ? 1 : 0;
        const std::string ref = side.pane + "." + side.quantity;
        if (pane >= view.panes.size() || !view.panes[pane].state) {
            out.reading = ref + ": the stop has no such pane";
            return out;
        }
        std::string error;
        value[i] = readQuantity(view.panes[pane], side.quantity, error);
        if (!value[i]) {
            out.reading = ref + ": " + error;
            return out;
        }
        if (value[i]->number) *value[i]->number *= side.factor;
        shown[i] = (side.factor != 1.0 ? ClaimValue{side.factor, {}}.shown() + "*" : "") + ref + " = " + value[i]->shown();
    }
    out.reading = shown[0] + " " + claim.op + " " + shown[1];
    if (value[0]->number && value[1]->number) {
        out.holds = compare(*value[0]->number, claim.op, *value[1]->number);
    } else if (!value[0]->number && !value[1]->number) {
        out.holds = (value[0]->word == value[1]->word) == (claim.op == "==");
    } else {
        out.reading += " (a number compared with a name)";
    }
    return out;
}

namespace {

/// The caption without what it quotes (between straight or curly double quotes).
std::string unquoted(const std::string& caption) {
    std::string out;
    bool inside = false;
    for (std::size_t i = 0; i < caption.size(); ++i) {
        if (caption[i] == '"') {
            inside = !inside;
            out += ' ';
            continue;
        }
        if (!inside) out += caption[i];
    }
    return out;
}

}  // namespace

std::vector<std::string> captionSlips(const std::string& caption, const std::vector<Claim>& claims, const ClaimView& view) {
    std::vector<std::string> slips;
    const std::string own = unquoted(caption);
    const bool compared = view.panes.size() > 1;
    // Panes: "Left: ...; right: ..." or "the right pane" only where the stop compares
    static const std::regex pane(R"(\b([Ll]eft|[Rr]ight)( pane|:))");
    if (std::smatch m; !compared && std::regex_search(own, m, pane))
        slips.push_back("the caption names the " + m.str(1) + " pane, but the stop shows one picture");
    // Paths: each named path is in focus in a pane, or listed by a panel the stop shows
    const bool listsAll = std::find_if(view.panels.begin(), view.panels.end(), [](const std::string& p) {
                              return p == "cache-tree";
                          }) != view.panels.end();
    std::vector<std::string> drawn;
    for (const ClaimPane& p : view.panes) {
        if (!p.state) continue;
        std::string path = focusPath(p);
        const bool tree = std::find(view.panels.begin(), view.panels.end(), "ray-tree") != view.panels.end();
        // The focused path, and with the ray-tree panel every path above it
        while (!path.empty()) {
            drawn.push_back(path);
            const auto slash = path.rfind('/');
            path = tree && slash != std::string::npos ? path.substr(0, slash) : std::string();
        }
        if (listsAll)
            for (int i = 0; i < p.state->session().cacheTree().size(); ++i)
                drawn.push_back(p.state->session().cacheTree().label(i));
    }
    static const std::regex pathName(R"(\beye(/(reflection|refraction|shadow \d+))*\b)");
    for (auto it = std::sregex_iterator(own.begin(), own.end(), pathName); it != std::sregex_iterator(); ++it) {
        const std::string path = it->str();
        // "eye rays" speaks of a kind of ray, not a path; a path has a slash or stands alone
        const std::size_t after = std::size_t(it->position() + it->length());
        if (path == "eye" && own.compare(after, 5, " rays") == 0) continue;
        if (path == "eye" && own.compare(after, 4, " ray") == 0) continue;
        if (path == "eye" && own.compare(after, 6, " point") == 0) continue;
        if (std::find(drawn.begin(), drawn.end(), path) == drawn.end())
            slips.push_back("the caption names path " + path + ", which no pane has in focus");
    }
    // Counts: every number the caption gives of its own is stated by a claim
    std::vector<double> stated;
    for (const Claim& c : claims)
        for (const Claim::Side* s : {&c.lhs, &c.rhs})
            if (s->number) stated.push_back(*s->number);
    std::string counted = std::regex_replace(own, std::regex(R"((Figure|Table) \d+|[A-Za-z_+]+:\d+|\d+x\d+(x\d+)*)"), " ");
    static const std::regex count(R"(\b(\d[\d,]*(\.\d+)?|two|three|four|five|six|seven|eight|nine|ten|eleven|twelve)\b)",
                                  std::regex::icase);
    static const char* const words[] = {"two", "three", "four", "five", "six", "seven", "eight", "nine", "ten", "eleven", "twelve"};
    for (auto it = std::sregex_iterator(counted.begin(), counted.end(), count); it != std::sregex_iterator(); ++it) {
        std::string w = it->str(1);
        if (w.find('.') != std::string::npos) continue;  // a ratio or a time, not a count
        std::transform(w.begin(), w.end(), w.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        double v = 0;
        if (std::isdigit(static_cast<unsigned char>(w[0]))) {
            w.erase(std::remove(w.begin(), w.end(), ','), w.end());
            v = std::strtod(w.c_str(), nullptr);
        } else {
            for (int k = 0; k < 11; ++k)
                if (w == words[k]) v = k + 2;
        }
        if (std::find(stated.begin(), stated.end(), v) == stated.end())
            slips.push_back("the caption gives the count '" + it->str(1) + "', which no claim of the stop states");
    }
    return slips;
}

}  // namespace rc
