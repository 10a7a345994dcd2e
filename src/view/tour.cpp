#include "view/tour.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <nlohmann/json.hpp>

#include "scene/builtin_scenes.h"
#include "view/claim.h"
#include "view/overlay_layers.h"
#include "view/session_state.h"
#include "view/viewer_settings.h"

namespace rc {

TourError::TourError(const std::string& f, int l, int c, const std::string& message)
    : std::runtime_error(f + ":" + std::to_string(l) + ":" + std::to_string(c) + ": " + message),
      file(f), line(l), column(c) {}

std::string TourStop::value(const std::string& key, const std::string& otherwise) const {
    for (const TourSetting& s : settings)
        if (s.key == key) return s.value;
    return otherwise;
}

const std::vector<std::string>& tourSettingNames() {
    // The viewer's settings, as their one reader declares them (rc::SettingsFlags)
    return settingNames();
}

namespace {

/// Reads the text a character at a time for nlohmann's lexer, counting what it has read,
/// so that the handler below knows where in the file each token ends.
struct CountingIterator {
    using iterator_category = std::forward_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;
    const char* at = nullptr;
    const char* begin = nullptr;
    std::size_t* read = nullptr;
    reference operator*() const { return *at; }
    CountingIterator& operator++() {
        ++at;
        *read = std::size_t(at - begin);
        return *this;
    }
    CountingIterator operator++(int) {
        CountingIterator before = *this;
        ++*this;
        return before;
    }
    bool operator==(const CountingIterator& o) const { return at == o.at; }
};

/// Builds a Tour from nlohmann's SAX events, checking its shape as it goes.
class TourBuilder {
public:
    using json = nlohmann::json;
    TourBuilder(const std::string& text, const std::string& file, Tour& out) : text_(text), file_(file), out_(out) {}
    std::size_t read = 0;  ///< characters the lexer has read

    bool null() { fail("a value must be a string, a number, true, false or an array of strings, not null"); }
    bool boolean(bool v) { return scalar(v ? "true" : "false", true, v); }
    bool number_integer(json::number_integer_t v) { return scalar(std::to_string(v)); }
    bool number_unsigned(json::number_unsigned_t v) { return scalar(std::to_string(v)); }
    bool number_float(json::number_float_t, const json::string_t& literal) { return scalar(literal); }
    bool string(json::string_t& v) { return scalar(v, false, true, true); }
    bool binary(json::binary_t&) { fail("binary values are not JSON text"); }

    bool start_object(std::size_t) {
        switch (where_) {
            case Where::Start: where_ = Where::Top; return true;
            case Where::Stops:
                out_.stops.emplace_back();
                out_.stops.back().line = lineAt(read - 1).first;
                out_.stops.back().column = lineAt(read - 1).second;
                where_ = Where::Stop;
                return true;
            default: fail(where_ == Where::Top ? "the tour's '" + key_ + "' must not be an object"
                                               : "'" + key_ + "' must be a string, a number, true or an array of strings");
        }
    }
    bool end_object() {
        if (where_ == Where::Stop) {
            const TourStop& s = out_.stops.back();
            const std::string which = "stop " + std::to_string(out_.stops.size());
            for (const char* required : {"title", "caption"})
                if ((std::string(required) == "title" ? s.title : s.caption).empty())
                    failAt(s.line, s.column, which + " has no '" + required + "'");
            if (s.value("scene").empty()) failAt(s.line, s.column, which + " has no 'scene'");
            where_ = Where::Stops;
        } else if (where_ == Where::Top) {
            if (!sawStops_) fail("a tour needs a 'stops' array");
            where_ = Where::Done;
        }
        return true;
    }
    bool start_array(std::size_t) {
        if (where_ == Where::Top && key_ == "stops") {
            where_ = Where::Stops;
            sawStops_ = true;
            return true;
        }
        if (where_ == Where::Stop && !isText(key_)) {
            where_ = Where::List;
            list_.clear();
            return true;
        }
        fail(where_ == Where::Start ? "a tour is an object with a 'stops' array, not an array"
                                    : "'" + key_ + "' must not be an array");
    }
    bool end_array() {
        if (where_ == Where::Stops) {
            if (out_.stops.empty()) fail("a tour needs at least one stop");
            where_ = Where::Top;
            return true;
        }
        // An array of strings: one setting, its items joined with commas; or the claims
        where_ = Where::Stop;
        if (key_ == "claims") {
            out_.stops.back().claims = list_;
            return true;
        }
        std::string joined;
        for (const std::string& item : list_) joined += (joined.empty() ? "" : ",") + item;
        out_.stops.back().settings.push_back({key_, joined, keyLine_, keyColumn_});
        return true;
    }
    bool key(json::string_t& k) {
        key_ = k;
        // The lexer has just read the key's closing quote: point at its opening one
        const auto [line, column] = lineAt(read >= k.size() + 2 ? read - k.size() - 2 : 0);
        keyLine_ = line;
        keyColumn_ = column;
        if (where_ == Where::Top) {
            if (k != "title" && k != "stops" && k != "description")
                failAt(keyLine_, keyColumn_, "a tour holds 'title', 'description' and 'stops', not '" + k + "'");
        } else if (where_ == Where::Stop) {
            const auto& names = tourSettingNames();
            if (k == "claims") {
                out_.stops.back().claimsLine = keyLine_;
                out_.stops.back().claimsColumn = keyColumn_;
            } else if (!isText(k) && std::find(names.begin(), names.end(), k) == names.end()) {
                failAt(keyLine_, keyColumn_, "unknown stop setting '" + k + "' (a stop holds title, caption, page, claims and " + joinedNames() + ")");
            }
            for (const TourSetting& s : out_.stops.back().settings)
                if (s.key == k) failAt(keyLine_, keyColumn_, "stop " + std::to_string(out_.stops.size()) + " sets '" + k + "' twice");
        }
        return true;
    }
    bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& e) {
        // nlohmann's message starts "[json.exception.parse_error.101] parse error at line 1, column 2: "
        std::string why = e.what();
        if (const auto colon = why.find(": "); colon != std::string::npos) why = why.substr(colon + 2);
        const auto [line, column] = lineAt(position > 0 ? position - 1 : 0);
        failAt(line, column, "not valid JSON: " + why);
    }

private:
    enum class Where { Start, Top, Stops, Stop, List, Done };
    static bool isText(const std::string& k) { return k == "title" || k == "caption" || k == "page"; }

    /// A value: the tour's title, a stop's title or caption, a setting, or an item of a list.
    bool scalar(const std::string& v, bool isBool = false, bool truth = true, bool isString = false) {
        switch (where_) {
            case Where::Top:
                if (key_ == "stops") fail("'stops' must be an array of stops");
                if (!isString) fail("the tour's '" + key_ + "' must be a string");
                if (key_ == "title") out_.title = v;
                return true;
            case Where::Stop: {
                TourStop& s = out_.stops.back();
                if (key_ == "claims") {
                    if (!isString || v.empty()) fail("a stop's 'claims' must be a string or an array of strings");
                    s.claims.push_back(v);
                } else if (isText(key_)) {
                    if (!isString || v.empty()) fail("a stop's '" + key_ + "' must be a non-empty string");
                    (key_ == "title" ? s.title : key_ == "caption" ? s.caption : s.page) = v;
                } else if (!isBool) {
                    s.settings.push_back({key_, v, keyLine_, keyColumn_});
                } else if (truth) {
                    s.settings.push_back({key_, "", keyLine_, keyColumn_});  // a switch
                }
                return true;
            }
            case Where::List:
                if (!isString) fail("the items of '" + key_ + "' must be strings");
                list_.push_back(v);
                return true;
            case Where::Stops: fail("every stop must be an object");
            default: fail("a tour is an object with a 'stops' array");
        }
    }
    std::pair<int, int> lineAt(std::size_t offset) const {
        offset = std::min(offset, text_.size());
        int line = 1, column = 1;
        for (std::size_t i = 0; i < offset; ++i) {
            if (text_[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        return {line, column};
    }
    static std::string joinedNames() {
        std::string all;
        for (const std::string& n : tourSettingNames()) all += (all.empty() ? "" : ", ") + n;
        return all;
    }
    [[noreturn]] void fail(const std::string& message) const {
        const auto [line, column] = lineAt(read > 0 ? read - 1 : 0);
        failAt(line, column, message);
    }
    [[noreturn]] void failAt(int line, int column, const std::string& message) const {
        throw TourError(file_, line, column, message);
    }

    const std::string& text_;
    const std::string& file_;
    Tour& out_;
    Where where_ = Where::Start;
    bool sawStops_ = false;
    std::string key_;
    int keyLine_ = 0, keyColumn_ = 0;
    std::vector<std::string> list_;
};

}  // namespace

Tour parseTour(const std::string& text, const std::string& file) {
    Tour tour;
    tour.file = file;
    TourBuilder builder(text, file, tour);
    const CountingIterator first{text.data(), text.data(), &builder.read};
    const CountingIterator last{text.data() + text.size(), text.data(), &builder.read};
    nlohmann::json::sax_parse(first, last, &builder);
    if (tour.stops.empty()) throw TourError(file, 1, 1, "a tour needs a 'stops' array with at least one stop");
    return tour;
}

Tour loadTour(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw TourError(path, 0, 0, "cannot read the tour file");
    std::ostringstream text;
    text << in.rdbuf();
    return parseTour(text.str(), path);
}

}  // namespace rc

namespace rc {

std::string stopScene(const Tour& tour, const TourStop& stop) {
    const std::string spec = stop.value("scene");
    const std::filesystem::path given(spec);
    if (given.is_absolute()) return spec;
    const std::filesystem::path beside = std::filesystem::path(tour.file).parent_path() / given;
    std::error_code ec;
    // A file beside the tour; failing that, one ending in .nff is still meant to be beside it
    if (std::filesystem::is_regular_file(beside, ec) || given.extension() == ".nff") return beside.lexically_normal().string();
    return spec;
}

void checkStop(const Tour& tour, int k) {
    const TourStop& st = tour.stops.at(std::size_t(k - 1));
    const std::string which = "stop " + std::to_string(k) + " (" + st.title + "): ";
    auto failAt = [&](const std::string& key, const std::string& why) {
        int line = st.line, column = st.column;
        for (const TourSetting& s : st.settings)
            if (s.key == key) line = s.line, column = s.column;
        if (key == "claims" && st.claimsLine > 0) line = st.claimsLine, column = st.claimsColumn;
        throw TourError(tour.file, line, column, which + key + ": " + why);
    };
    // The scene opens
    std::shared_ptr<const Scene> scene;
    try {
        scene = std::make_shared<const Scene>(loadScene(stopScene(tour, st)));
    } catch (const std::exception& e) {
        failAt("scene", e.what());
    }
    // The stop's settings, read as the viewer reads them (rc::stopSettings: names and limits)
    const ViewerSettings v = stopSettings(tour, k);
    // The image's size, as the viewer takes it: the stop's, else the scene's own
    const int w = v.width > 0 ? v.width : scene->camera.width;
    const int h = v.height > 0 ? v.height : scene->camera.height;
    // The focus rectangle and the selected pixel lie in the image
    if (const auto& r = v.focus; r && ((*r)[2] > w || (*r)[3] > h))
        failAt("focus", "'" + st.value("focus") + "' is not a rectangle x0,y0,x1,y1 inside the " + std::to_string(w) + "x" +
                            std::to_string(h) + " image");
    if (v.select) {
        const StopSelect& sel = *v.select;
        if (sel.x >= w || sel.y >= h)
            failAt("select", "pixel '" + std::to_string(sel.x) + "," + std::to_string(sel.y) + "' lies outside the " +
                                 std::to_string(w) + "x" + std::to_string(h) + " image");
        // The path is a ray of that pixel: its scanline traced as the stop traces it
        if (!sel.path.empty()) {
            RenderOptions ro;
            ro.width = w;
            ro.height = h;
            ro.rowBegin = sel.y;
            ro.rowEnd = sel.y + 1;
            ro.shading.sampling = v.sampling;
            try {
                SessionState s({scene, ro});
                s.runUntil(RunGoal::ToEnd, 0);
                std::string why;
                if (eventAtPath(s, sel.y * w + sel.x, sel.path, why) < 0) failAt("select", why);
            } catch (const TourError&) {
                throw;
            } catch (const std::exception& e) {
                failAt("select", e.what());
            }
        }
    }
    // The claims read quantities the stop draws
    std::vector<Claim> claims;
    if (const std::string why = parseStopClaims(st, claims); !why.empty()) failAt("claims", why);
}

void checkTour(const Tour& tour) {
    for (int k = 1; k <= int(tour.stops.size()); ++k) checkStop(tour, k);
}

}  // namespace rc
