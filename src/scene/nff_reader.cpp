#include "scene/nff_reader.h"
#include "scene/decimal.h"

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <system_error>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

namespace rc {

namespace {

/// One token: a run of printable, non-blank bytes. Empty text means end of file.
struct Token {
    std::string_view text;
    int line = 1;
    int column = 1;
    bool end() const { return text.empty(); }
};

/// Concatenates strings by appending: GCC 12 warns falsely (-Wrestrict, PR105651)
/// about chains of `"literal" + std::string` at -O3.
template <class... Parts>
std::string cat(const Parts&... parts) {
    std::string s;
    (s.append(std::string_view(parts)), ...);
    return s;
}

/// A token, or "end of file", quoted for a message; long tokens are shortened.
std::string describe(const Token& t) {
    if (t.end()) return "end of file";
    constexpr std::size_t maxShown = 40;
    std::string s = "'";
    s += t.text.substr(0, maxShown);
    if (t.text.size() > maxShown) s += "...";
    s += "'";
    return s;
}

bool isBlank(unsigned char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }
bool isPrintable(unsigned char c) { return c > 0x20 && c < 0x7f; }

/// Splits the text into tokens, skipping blanks and comments, and keeps the line and
/// column of each. Copying a Lexer is cheap: that is how the parser looks ahead.
class Lexer {
public:
    Lexer(std::string_view text, const std::string& file) : text_(text), file_(&file) {}

    Token next() {
        while (pos_ < text_.size()) {
            const unsigned char c = static_cast<unsigned char>(text_[pos_]);
            if (c == '\n') {
                newline(1);
            } else if (c == '\r') {
                // "\r\n" is one line break; a lone '\r' (old Mac files) is one too
                if (pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') newline(2);
                else newline(1);
            } else if (isBlank(c)) {
                ++pos_;
                ++col_;
            } else if (c == '#') {
                skipComment();
            } else if (isPrintable(c)) {
                const std::size_t start = pos_;
                const int startCol = col_;
                while (pos_ < text_.size() && isPrintable(static_cast<unsigned char>(text_[pos_]))) {
                    ++pos_;
                    ++col_;
                }
                // A token glued to a non-printable byte: report the byte, not the token
                if (pos_ < text_.size()) {
                    const unsigned char after = static_cast<unsigned char>(text_[pos_]);
                    if (!isBlank(after) && after != '\n' && after != '\r') badByte(after);
                }
                endLine_ = line_;
                endCol_ = col_;
                return {text_.substr(start, pos_ - start), line_, startCol};
            } else {
                badByte(c);
            }
        }
        return {{}, endLine_, endCol_};
    }

    Token peek() const {
        Lexer copy = *this;
        return copy.next();
    }

private:
    void newline(std::size_t bytes) {
        pos_ += bytes;
        ++line_;
        col_ = 1;
    }

    // Comments may hold any text (UTF-8 included) but no control bytes
    void skipComment() {
        while (pos_ < text_.size()) {
            const unsigned char c = static_cast<unsigned char>(text_[pos_]);
            if (c == '\n' || c == '\r') return;
            if ((c < 0x20 && !isBlank(c)) || c == 0x7f) badByte(c);
            ++pos_;
            ++col_;
        }
    }

    [[noreturn]] void badByte(unsigned char c) const {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02x", unsigned(c));
        throw SceneError(*file_, line_, col_,
                         cat("non-printable byte ", hex, " (is this a binary file?)"));
    }

    std::string_view text_;
    const std::string* file_;
    std::size_t pos_ = 0;
    int line_ = 1, col_ = 1;
    int endLine_ = 1, endCol_ = 1;  // just past the last token: where "end of file" is
};

enum class NumberStatus { Ok, NotANumber, NotFinite, OutOfRange };

/// Parses a whole token as a decimal floating-point number ("1.0abc" is not one).
NumberStatus toNumber(std::string_view s, double& value) {
    // Numbers take no leading '+'; NFF writers sometimes emit one
    if (s.size() > 1 && s[0] == '+' && s[1] != '+' && s[1] != '-') s.remove_prefix(1);
    if (s.empty()) return NumberStatus::NotANumber;
    const DecimalStatus status = parseDecimal(s, value);
    if (status == DecimalStatus::OutOfRange) return NumberStatus::OutOfRange;
    if (status != DecimalStatus::Ok) return NumberStatus::NotANumber;
    if (!std::isfinite(value)) return NumberStatus::NotFinite;
    if (std::abs(value) > NffLimits::maxMagnitude) return NumberStatus::OutOfRange;
    return NumberStatus::Ok;
}

/// What a number is for, as a message names it: "sphere radius", "polygon vertex 3 y".
struct What {
    const char* item;
    long index = -1;  ///< 0-based; shown 1-based
    const char* part = nullptr;

    std::string str() const {
        std::string s = item;
        if (index >= 0) {
            s += " ";
            s += std::to_string(index + 1);
        }
        if (part) {
            s += " ";
            s += part;
        }
        return s;
    }
};

constexpr std::array<const char*, 3> kXyz = {"x", "y", "z"};
constexpr std::array<const char*, 3> kRgb = {"red", "green", "blue"};

/// The `v` block keywords, in the order NFF writes them.
constexpr std::array<std::string_view, 6> kViewKeywords = {"from",  "at",     "up",
                                                           "angle", "hither", "resolution"};
enum ViewKey { From, At, Up, Angle, Hither, Resolution };

int viewKeyword(std::string_view s) {
    for (std::size_t i = 0; i < kViewKeywords.size(); ++i)
        if (s == kViewKeywords[i]) return int(i);
    return -1;
}

class Parser {
public:
    Parser(std::string_view text, const std::string& file, long maxPrimitives)
        : lex_(text, file), file_(file), maxPrimitives_(maxPrimitives) {}

    Scene parse() {
        bool anyToken = false;
        for (;;) {
            const Token t = lex_.next();
            if (t.end()) {
                if (!haveView_)
                    fail(t, anyToken ? "no view ('v') block" : "empty file: no view ('v') block");
                break;
            }
            anyToken = true;
            const std::string_view k = t.text;
            if (k == "v") view(t);
            else if (k == "b") scene_.background = colour(What{"background"});
            else if (k == "l") light();
            else if (k == "f") material();
            else if (k == "s") sphere(t);
            else if (k == "p") polygon(t, false);
            else if (k == "pp") polygon(t, true);
            else if (k == "c") cone(t);
            else if (viewKeyword(k) >= 0)
                fail(t, "'", k, "' outside a view ('v') block");
            else unsupported(t);
        }
        scene_.finalize();
        return std::move(scene_);
    }

private:
    /// Throws a SceneError at `t` whose message is the concatenation of `parts`.
    template <class... Parts>
    [[noreturn]] void fail(const Token& t, const Parts&... parts) const {
        throw SceneError(file_, t.line, t.column, cat(parts...));
    }

    /// Reads one number; the token comes back too so that range errors can point at it.
    std::pair<double, Token> numberAt(const What& what) {
        const Token t = lex_.next();
        double v = 0.0;
        switch (t.end() ? NumberStatus::NotANumber : toNumber(t.text, v)) {
            case NumberStatus::Ok: return {v, t};
            case NumberStatus::NotANumber:
                fail(t, "expected a number for ", what.str(), ", found ", describe(t));
            case NumberStatus::NotFinite:
                fail(t, "NaN or infinity is not allowed (", what.str(), " is ", describe(t), ")");
            case NumberStatus::OutOfRange:
                fail(t, "number out of range for ", what.str(), ": ", describe(t));
        }
        fail(t, "internal error");  // not reached
    }

    double number(const What& what) { return numberAt(what).first; }

    Vec3 vec3(const char* item, long index = -1) {
        Vec3 v;
        for (int i = 0; i < 3; ++i) v[i] = number(What{item, index, kXyz[i]});
        return v;
    }

    Vec3 colour(const What& what) {
        Vec3 c;
        for (int i = 0; i < 3; ++i) {
            const auto [v, t] = numberAt(What{what.item, what.index, kRgb[i]});
            if (v < 0.0) fail(t, what.str(), " ", kRgb[i], " must not be negative, found ", describe(t));
            c[i] = v;
        }
        return c;
    }

    /// A whole number in [0, max], checked before anything is allocated for it.
    long count(const What& what, long max) {
        const auto [v, t] = numberAt(what);
        if (v != std::floor(v)) fail(t, what.str(), " must be a whole number, found ", describe(t));
        if (v < 0.0) fail(t, what.str(), " must not be negative, found ", describe(t));
        if (v > double(max))
            fail(t, what.str(), " ", describe(t), " exceeds the limit of ", std::to_string(max));
        return long(v);
    }

    bool nextIsNumber() const {
        const Token t = lex_.peek();
        double v = 0.0;
        return !t.end() && toNumber(t.text, v) != NumberStatus::NotANumber;
    }

    void view(const Token& v) {
        if (haveView_)
            fail(v, "a second view ('v') block (the first is at line ", std::to_string(viewLine_), ")");
        haveView_ = true;
        viewLine_ = v.line;
        Camera& cam = scene_.camera;
        std::array<std::optional<Token>, kViewKeywords.size()> seen;
        for (;;) {
            const Token t = lex_.peek();
            const int k = t.end() ? -1 : viewKeyword(t.text);
            if (k < 0) break;
            lex_.next();
            if (seen[k]) fail(t, "'", t.text, "' appears twice in the view block");
            seen[k] = t;
            switch (k) {
                case From: cam.from = vec3("view from"); break;
                case At: cam.at = vec3("view at"); break;
                case Up: cam.up = vec3("view up"); break;
                case Angle: {
                    const auto [a, at] = numberAt(What{"view angle"});
                    if (!(a > 0.0 && a < 180.0))
                        fail(at, "view angle must be between 0 and 180 degrees (exclusive), found ",
                             describe(at));
                    cam.angle = a;
                    break;
                }
                case Hither: {
                    const auto [h, ht] = numberAt(What{"view hither"});
                    if (h < 0.0) fail(ht, "view hither must not be negative, found ", describe(ht));
                    cam.hither = h;
                    break;
                }
                case Resolution: {
                    const What dims[2] = {What{"resolution width"}, What{"resolution height"}};
                    int* out[2] = {&cam.width, &cam.height};
                    for (int i = 0; i < 2; ++i) {
                        const auto [r, rt] = numberAt(dims[i]);
                        if (!(r >= 1.0 && r <= double(NffLimits::maxResolution)) || r != std::floor(r))
                            fail(rt, dims[i].str(), " must be a whole number from 1 to ",
                                 std::to_string(NffLimits::maxResolution), ", found ", describe(rt));
                        *out[i] = int(r);
                    }
                    break;
                }
            }
        }
        for (int k : {From, At, Up, Angle, Resolution})
            if (!seen[k])
                fail(v, "the view ('v') block has no '", kViewKeywords[k], "'");
        const Vec3 dir = cam.at - cam.from;
        const double dist = glm::length(dir);
        if (!(dist > 0.0)) fail(*seen[At], "view 'at' is the same point as 'from'");
        if (!std::isfinite(dist)) fail(*seen[At], "view 'at' is too far from 'from'");
        const double up = glm::length(cam.up);
        if (!(up > 0.0)) fail(*seen[Up], "view 'up' is the zero vector");
        if (!(glm::length(glm::cross(dir / dist, cam.up / up)) > 1e-9))
            fail(*seen[Up], "view 'up' is parallel to the viewing direction (from -> at)");
    }

    void light() {
        Light l;
        l.position = vec3("light position");
        // The colour is optional: present when the next token is a number
        if (nextIsNumber()) l.color = colour(What{"light colour"});
        scene_.lights.push_back(l);
    }

    void material() {
        Material m;
        m.color = colour(What{"material colour"});
        const auto nonNegative = [&](const char* name) {
            const auto [v, t] = numberAt(What{name});
            if (v < 0.0) fail(t, name, " must not be negative, found ", describe(t));
            return v;
        };
        m.kd = nonNegative("material Kd");
        m.ks = nonNegative("material Ks");
        m.shine = nonNegative("material Shine");
        m.kt = nonNegative("material T");
        // SPD writes ior 0 for opaque materials: the index only matters for a transmitter
        const auto [ior, it] = numberAt(What{"material index of refraction"});
        if (m.kt > 0.0 && !(ior > 0.0))
            fail(it, "material index of refraction must be positive for a transmitting material (T > 0), found ",
                 describe(it));
        if (ior < 0.0) fail(it, "material index of refraction must not be negative, found ", describe(it));
        m.ior = m.kt > 0.0 ? ior : 1.0;
        scene_.materials.push_back(m);
        currentMaterial_ = int(scene_.materials.size()) - 1;
    }

    int materialForPrimitive() {
        if (currentMaterial_ < 0) {
            scene_.materials.push_back(Material{});  // white, diffuse
            currentMaterial_ = int(scene_.materials.size()) - 1;
        }
        return currentMaterial_;
    }

    void checkPrimitiveLimit(const Token& kw) const {
        if (long(scene_.objects.size()) >= maxPrimitives_)
            fail(kw, "more than ", std::to_string(maxPrimitives_), " primitives");
    }

    void sphere(const Token& kw) {
        checkPrimitiveLimit(kw);
        Sphere s;
        s.c = vec3("sphere centre");
        const auto [r, rt] = numberAt(What{"sphere radius"});
        if (!(r > 0.0)) fail(rt, "sphere radius must be positive, found ", describe(rt));
        s.r = r;
        scene_.addSphere(s, materialForPrimitive());
    }

    void polygon(const Token& kw, bool withNormals) {
        checkPrimitiveLimit(kw);
        const char* item = withNormals ? "polygon patch" : "polygon";
        const Token countToken = lex_.peek();
        const long n = count(What{withNormals ? "polygon patch vertex count" : "polygon vertex count"},
                             NffLimits::maxPolygonVertices);
        if (n < 3)
            fail(countToken, "a ", item, " needs at least 3 vertices, found ", describe(countToken));
        std::vector<Vec3> vertices, normals;
        vertices.reserve(std::size_t(n));
        if (withNormals) normals.reserve(std::size_t(n));
        for (long i = 0; i < n; ++i) {
            vertices.push_back(vec3(withNormals ? "polygon patch vertex" : "polygon vertex", i));
            if (withNormals) normals.push_back(vec3("polygon patch normal", i));
        }
        Polygon poly;
        if (auto err = makePolygon(std::move(vertices), std::move(normals), poly)) {
            if (*err != kZeroAreaPolygon) fail(kw, *err);
            // No ray can hit a polygon of zero area: it is left out, and said so
            ++scene_.skippedCount;
            if (scene_.skipped.size() < NffLimits::maxSkippedNamed)
                scene_.skipped.push_back(
                    SceneError(file_, kw.line, kw.column,
                               cat(item, " of zero area skipped (collinear or coincident vertices: no ray can hit it)"))
                        .what());
            return;
        }
        scene_.addPolygon(std::move(poly), materialForPrimitive());
    }

    void cone(const Token& kw) {
        checkPrimitiveLimit(kw);
        const Vec3 base = vec3("cone base centre");
        const auto [rb, rbt] = numberAt(What{"cone base radius"});
        if (rb < 0.0) fail(rbt, "cone base radius must not be negative, found ", describe(rbt));
        const Token apexToken = lex_.peek();
        const Vec3 apex = vec3("cone apex centre");
        const auto [ra, rat] = numberAt(What{"cone apex radius"});
        if (ra < 0.0) fail(rat, "cone apex radius must not be negative, found ", describe(rat));
        if (!(rb > 0.0 || ra > 0.0)) fail(rat, "cone has both radii zero (a line, not a surface)");
        TruncatedCone c;
        if (auto err = makeTruncatedCone(base, rb, apex, ra, c)) fail(apexToken, *err);
        scene_.addCone(c, materialForPrimitive());
    }

    [[noreturn]] void unsupported(const Token& t) const {
        const std::string_view k = t.text;
        double v = 0.0;
        if (toNumber(k, v) != NumberStatus::NotANumber)
            fail(t, "unexpected number ", describe(t),
                 " where an NFF keyword was expected (too many numbers before it?)");
        const unsigned char c0 = static_cast<unsigned char>(k[0]);
        const bool word = (c0 >= 'a' && c0 <= 'z') || (c0 >= 'A' && c0 <= 'Z');
        if (!word) fail(t, "unexpected ", describe(t), " where an NFF keyword was expected");
        std::string what;
        if (k == "tpp") what = " (textured polygonal patch)";
        else if (k == "tp" || k == "tt") what = " (textured polygon)";
        fail(t, "unsupported NFF primitive ", describe(t), what);
    }

    Lexer lex_;
    const std::string& file_;
    long maxPrimitives_;
    Scene scene_;
    int currentMaterial_ = -1;
    bool haveView_ = false;
    int viewLine_ = 0;
};

}  // namespace

Scene parseNff(std::string_view text, const std::string& fileName, long maxPrimitives) {
    if (text.size() > NffLimits::maxFileBytes)
        throw SceneError(fileName, 0, 0,
                         cat("input is larger than ", std::to_string(NffLimits::maxFileBytes), " bytes"));
    // A UTF-8 byte-order mark (some editors write one) is not part of the text
    constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
    if (text.substr(0, kByteOrderMark.size()) == kByteOrderMark) text.remove_prefix(kByteOrderMark.size());
    Scene scene = Parser(text, fileName, maxPrimitives).parse();
    scene.name = std::filesystem::path(fileName).stem().string();
    return scene;
}

Scene readNffFile(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw SceneError(path, 0, 0, "cannot read: it is a directory");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path, 0, 0, cat("cannot open file: ", std::strerror(errno)));
    std::string text;
    char buffer[1 << 16];
    while (in) {
        in.read(buffer, sizeof buffer);
        text.append(buffer, std::size_t(in.gcount()));
        if (text.size() > NffLimits::maxFileBytes)
            throw SceneError(path, 0, 0,
                             cat("file is larger than ", std::to_string(NffLimits::maxFileBytes), " bytes"));
    }
    if (in.bad()) throw SceneError(path, 0, 0, "read error");
    return parseNff(text, path);
}

}  // namespace rc
