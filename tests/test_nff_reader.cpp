// Tests of the NFF reader: the SPD scenes, lenient good input, and every kind of
// malformed input reported at its exact file:line:column.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "scene/nff_reader.h"

using namespace rc;

namespace {

const std::string kScenes = RAYCACHE_SCENES_DIR;
const std::string kData = RAYCACHE_TEST_DATA;

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    REQUIRE(in);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// How many lines of an NFF file start with keyword `k`: an independent count.
int countLines(const std::string& text, const std::string& k) {
    std::istringstream in(text);
    std::string line;
    int n = 0;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string first;
        if (words >> first && first == k) ++n;
    }
    return n;
}

const char* kView =
    "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\nhither 0.01\nresolution 64 64\n";

/// Runs `f`, which must throw a SceneError, and returns it.
template <class F>
SceneError errorOf(F f) {
    try {
        f();
    } catch (const SceneError& e) {
        return e;
    }
    FAIL("no SceneError was thrown");
    return SceneError("", 0, 0, "");
}

}  // namespace

TEST_CASE("the SPD scenes parse with the counts their files hold", "[nff]") {
    for (const char* name : {"balls1", "balls2", "shells1"}) {
        const std::string path = kScenes + "/" + name + ".nff";
        const std::string text = slurp(path);
        INFO(path);
        const Scene s = readNffFile(path);
        CHECK(s.name == name);
        CHECK(int(s.spheres.size()) == countLines(text, "s"));
        CHECK(int(s.polygons.size()) == countLines(text, "p") + countLines(text, "pp"));
        CHECK(int(s.lights.size()) == countLines(text, "l"));
        CHECK(int(s.materials.size()) == countLines(text, "f"));
        CHECK(s.size() == int(s.spheres.size() + s.polygons.size()));
        CHECK(s.camera.width == 512);
        CHECK(s.camera.height == 512);
        CHECK(s.camera.angle == 45.0);
        CHECK(s.bound.r > 0.0);
        CHECK(s.background.x == Approx(0.078));
    }
}

TEST_CASE("balls1 and balls2: spheres, one ground polygon, three lights", "[nff]") {
    for (const char* name : {"balls1", "balls2"}) {
        const Scene s = readNffFile(kScenes + "/" + name + ".nff");
        CHECK(s.spheres.size() > 1);
        CHECK(s.polygons.size() == 1);
        CHECK(s.lights.size() == 3);
        CHECK(s.camera.from == Vec3(2.1, 1.3, 1.7));
        CHECK(s.camera.up == Vec3(0.0, 0.0, 1.0));
        CHECK(s.camera.hither == 0.01);
        // The ground polygon comes first and has the first material
        CHECK(s.objects[0].shape == Shape::Polygon);
        CHECK(s.objects[0].material == 0);
        CHECK(s.materials[0].shine == 100000.0);
        CHECK(s.objects[1].material == 1);
        CHECK(s.spheres[0].r == 0.5);
        CHECK(std::abs(s.polygons[0].normal.z) == Approx(1.0));
    }
}

TEST_CASE("a lenient hand-written file: b before v, keywords sharing lines, pp", "[nff]") {
    const Scene s = readNffFile(kData + "/good/mixed.nff");
    CHECK(s.name == "mixed");
    CHECK(s.background == Vec3(0.1, 0.2, 0.3));
    CHECK(s.camera.from == Vec3(0, 0, 10));
    CHECK(s.camera.angle == 40.0);
    CHECK(s.camera.hither == 0.5);
    CHECK(s.camera.width == 32);
    CHECK(s.camera.height == 24);
    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[0].color == Vec3(1.0));
    CHECK(s.lights[1].color == Vec3(0.5, 0.25, 1.0));
    REQUIRE(s.spheres.size() == 2);
    CHECK(s.spheres[1].c == Vec3(2, 0, 0));
    CHECK(s.spheres[1].r == 0.5);
    REQUIRE(s.polygons.size() == 2);
    CHECK(s.polygons[0].vertexNormals.size() == 3);
    CHECK(glm::length(s.polygons[0].vertexNormals[2]) == Approx(1.0));
    CHECK(s.polygons[1].vertices.size() == 4);
    CHECK(s.polygons[1].vertexNormals.empty());
    // Default white diffuse, then the two 'f' materials
    REQUIRE(s.materials.size() == 3);
    CHECK(s.objects[0].material == 0);
    CHECK(s.materials[0].color == Vec3(1.0));
    CHECK(s.materials[0].kd == 1.0);
    CHECK(s.materials[0].ks == 0.0);
    CHECK(s.objects[1].material == 1);
    CHECK(s.objects[2].material == 1);
    CHECK(s.objects[3].material == 2);
    CHECK(s.materials[2].kt == 0.9);
    CHECK(s.materials[2].ior == 1.5);
}

TEST_CASE("view keywords in any order, hither optional, CRLF line ends", "[nff]") {
    const Scene r = readNffFile(kData + "/good/reordered_view.nff");
    CHECK(r.camera.width == 16);
    CHECK(r.camera.height == 8);
    CHECK(r.camera.angle == 30.0);
    CHECK(r.camera.up == Vec3(0, 0, 1));
    CHECK(r.camera.from == Vec3(-4, -4, 1));
    CHECK(r.camera.hither == Camera{}.hither);
    CHECK(r.spheres.at(0).r == 0.5);

    const Scene c = readNffFile(kData + "/good/crlf.nff");
    CHECK(c.spheres.size() == 1);
    CHECK(c.camera.width == 8);
}

TEST_CASE("inline NFF: tokens spread over lines and several keywords on one line", "[nff]") {
    const std::string one = "v from 0 0 5 at 0 0 0 up 0 1 0 angle 45 hither 1 resolution 4 4 "
                            "l 0 9 0 s 0 0 0 1 s 3 0 0 1 # trailing comment s 9 9 9 9\n";
    const Scene a = parseNff(one, "one.nff");
    CHECK(a.spheres.size() == 2);
    CHECK(a.lights.size() == 1);

    const std::string spread = "# header comment\nb\n0\n0\n0\nv\nfrom\n0\n0\n5\nat 0 0\n0 up 0\n1\n0\n"
                               "angle\n45 hither 0.1 resolution\n4\n4\nl\n1\n2\n3\n"
                               "s\n1\n2\n3\n4\n";
    const Scene b = parseNff(spread, "spread");
    REQUIRE(b.spheres.size() == 1);
    CHECK(b.spheres[0].c == Vec3(1, 2, 3));
    CHECK(b.spheres[0].r == 4.0);
    CHECK(b.lights[0].position == Vec3(1, 2, 3));
    CHECK(b.lights[0].color == Vec3(1.0));
}

TEST_CASE("inline NFF: light colour is read only when numbers follow", "[nff]") {
    const Scene s = parseNff(std::string(kView) + "l 1 2 3\nl 4 5 6 0.1 0.2 0.3 l 7 8 9\ns 0 0 0 1\n", "l");
    REQUIRE(s.lights.size() == 3);
    CHECK(s.lights[0].color == Vec3(1.0));
    CHECK(s.lights[1].color == Vec3(0.1, 0.2, 0.3));
    CHECK(s.lights[2].position == Vec3(7, 8, 9));
    CHECK(s.lights[2].color == Vec3(1.0));
}

TEST_CASE("inline NFF: pp normals are normalised, numbers take '+' and exponents", "[nff]") {
    const Scene s = parseNff(std::string(kView) +
                                 "pp 3 0 0 0 0 0 2  1 0 0 0 0 +3e0  0 1 0 0 0.5 1\n"
                                 "s -1e0 +2. .5 1E-1\n",
                             "pp.nff");
    REQUIRE(s.polygons.size() == 1);
    for (const Vec3& n : s.polygons[0].vertexNormals) CHECK(glm::length(n) == Approx(1.0));
    CHECK(s.spheres.at(0).c == Vec3(-1.0, 2.0, 0.5));
    CHECK(s.spheres.at(0).r == 0.1);
}

TEST_CASE("inline NFF: a file with a view and no primitives is an empty scene", "[nff]") {
    const Scene s = parseNff(kView, "/some/dir/nothing.nff");
    CHECK(s.name == "nothing");
    CHECK(s.size() == 0);
}

namespace {
struct Bad {
    const char* file;
    int line;
    int column;
    const char* message;
};

// clang-format off
const Bad kMalformed[] = {
    {"cone_negative_radius",     8,  9, "cone base radius must not be negative, found '-1'"},
    {"cone_zero_radii",          8, 17, "cone has both radii zero"},
    {"cone_coincident_ends",     8, 11, "cone's base and apex centres coincide"},
    {"tpp",                      8,  1, "unsupported NFF primitive 'tpp'"},
    {"unknown_keyword",          8,  3, "unsupported NFF primitive 'sphere'"},
    {"truncated_sphere",         8,  8, "expected a number for sphere radius, found end of file"},
    {"truncated_polygon",       11,  6, "expected a number for polygon vertex 4 x, found end of file"},
    {"non_numeric",              8,  7, "expected a number for sphere centre z, found 'abc'"},
    {"number_with_suffix",       8,  9, "expected a number for sphere radius, found '1.0abc'"},
    {"nan",                      8,  3, "NaN or infinity is not allowed (sphere centre x is 'nan')"},
    {"inf_light",                8,  5, "NaN or infinity is not allowed (light position y is '-inf')"},
    {"huge_number",              8,  9, "number out of range for sphere radius: '1e999'"},
    {"negative_radius",          8,  9, "sphere radius must be positive, found '-1'"},
    {"zero_radius",              8,  9, "sphere radius must be positive, found '0'"},
    {"polygon_two_vertices",     8,  3, "a polygon needs at least 3 vertices, found '2'"},
    {"polygon_nonplanar",        8,  1, "polygon is not planar"},
    {"polygon_self_intersecting", 8, 1, "polygon crosses itself"},
    {"polygon_huge_count",       8,  3, "polygon vertex count '4000000000' exceeds the limit of 10000"},
    {"polygon_negative_count",   8,  3, "polygon vertex count must not be negative, found '-3'"},
    {"polygon_fractional_count", 8,  3, "polygon vertex count must be a whole number, found '3.5'"},
    {"resolution_zero",          7, 12, "resolution width must be a whole number from 1 to 16384, found '0'"},
    {"resolution_too_big",       7, 15, "resolution height must be a whole number from 1 to 16384, found '20000'"},
    {"angle_180",                5,  7, "view angle must be between 0 and 180 degrees"},
    {"angle_zero",               5,  7, "view angle must be between 0 and 180 degrees"},
    {"hither_negative",          6,  8, "view hither must not be negative"},
    {"up_zero",                  4,  1, "view 'up' is the zero vector"},
    {"up_parallel",              4,  1, "view 'up' is parallel to the viewing direction"},
    {"from_equals_at",           3,  1, "view 'at' is the same point as 'from'"},
    {"view_missing_resolution",  1,  1, "the view ('v') block has no 'resolution'"},
    {"no_view",                  2, 10, "no view ('v') block"},
    {"empty",                    1,  1, "empty file: no view ('v') block"},
    {"comments_only",            1,  1, "empty file: no view ('v') block"},
    {"binary",                   1,  1, "non-printable byte 0x7f"},
    {"nul_in_number",            8, 10, "non-printable byte 0x00"},
    {"control_in_comment",       8,  6, "non-printable byte 0x01"},
    {"utf8_token",               9,  4, "non-printable byte 0xc3"},
    {"duplicate_view",           9,  1, "a second view ('v') block (the first is at line 1)"},
    {"view_keyword_outside",     9,  1, "'from' outside a view ('v') block"},
    {"duplicate_from",           3, 10, "'from' appears twice in the view block"},
    {"stray_number",             8, 11, "unexpected number '2' where an NFF keyword was expected"},
    {"light_partial_colour",     9,  1, "expected a number for light colour blue, found 's'"},
    {"material_truncated",       9,  1, "expected a number for material Ks, found 's'"},
    {"material_transmitter_ior_zero", 8, 24, "must be positive for a transmitting material (T > 0), found '0'"},
    {"material_negative_ior",    8, 22, "material index of refraction must not be negative, found '-1'"},
    {"negative_colour",          1,  3, "background red must not be negative"},
    {"spread_over_lines",       11,  1, "sphere radius must be positive, found '-2'"},
    {"crlf",                     8,  9, "expected a number for sphere radius, found 'x'"},
    {"tabs",                     8,  9, "expected a number for sphere radius, found 'bad'"},
    {"pp_zero_normal",           8,  1, "zero or non-finite vertex normal"},
    {"pp_truncated",            10,  6, "expected a number for polygon patch normal 2 x, found end of file"},
    {"punctuation",              8, 11, "unexpected ';' where an NFF keyword was expected"},
};
// clang-format on
}  // namespace

TEST_CASE("malformed files are reported at file:line:column with a clear message", "[nff]") {
    STATIC_REQUIRE(std::size(kMalformed) >= 20);
    for (const Bad& bad : kMalformed) {
        const std::string path = kData + "/malformed/" + bad.file + ".nff";
        INFO(bad.file);
        const SceneError e = errorOf([&] { readNffFile(path); });
        const std::string prefix =
            path + ":" + std::to_string(bad.line) + ":" + std::to_string(bad.column) + ": ";
        const std::string what = e.what();
        INFO(what);
        CHECK(what.rfind(prefix, 0) == 0);
        CHECK(what.find(bad.message) != std::string::npos);
        CHECK(e.file == path);
        CHECK(e.line == bad.line);
        CHECK(e.column == bad.column);
        CHECK(e.message.find(bad.message) != std::string::npos);
    }
}

TEST_CASE("every file under tests/data/malformed is in the table", "[nff]") {
    // A file added without an expectation would silently go untested
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kData + "/malformed")) {
        const std::string stem = entry.path().stem().string();
        INFO(stem);
        CHECK(std::any_of(std::begin(kMalformed), std::end(kMalformed),
                          [&](const Bad& b) { return stem == b.file; }));
        ++files;
    }
    CHECK(files == int(std::size(kMalformed)));
}

TEST_CASE("absurd polygon counts are rejected before anything is allocated", "[nff]") {
    const SceneError e = errorOf([] { parseNff(std::string(kView) + "p 4000000000", "big"); });
    CHECK(e.line == 8);
    CHECK(e.column == 3);
    CHECK(e.message.find("exceeds the limit") != std::string::npos);
    const SceneError e2 = errorOf([] { parseNff(std::string(kView) + "pp 1e50", "big"); });
    CHECK(e2.message.find("exceeds the limit") != std::string::npos);
    const SceneError e5 = errorOf([] { parseNff(std::string(kView) + "pp 1e300", "big"); });
    CHECK(e5.message.find("out of range") != std::string::npos);
    const SceneError e3 = errorOf([] { parseNff(std::string(kView) + "p -4000000000", "neg"); });
    CHECK(e3.message.find("must not be negative") != std::string::npos);
    // Exactly at the limit is allowed up front (and then runs out of numbers)
    const SceneError e4 = errorOf([] { parseNff(std::string(kView) + "p 10000 0 0 0", "limit"); });
    CHECK(e4.message.find("polygon vertex 2 x, found end of file") != std::string::npos);
}

TEST_CASE("the primitive limit is enforced", "[nff]") {
    const std::string text = std::string(kView) + "s 0 0 0 1\ns 3 0 0 1\n  s 6 0 0 1\n";
    CHECK(parseNff(text, "ok", 3).size() == 3);
    const SceneError e = errorOf([&] { parseNff(text, "limited", 2); });
    CHECK(e.line == 10);
    CHECK(e.column == 3);
    CHECK(e.message == "more than 2 primitives");
}

TEST_CASE("unreadable files are reported at line 0", "[nff]") {
    const SceneError e = errorOf([] { readNffFile(kData + "/no/such/file.nff"); });
    CHECK(e.line == 0);
    CHECK(e.column == 0);
    CHECK(e.message.find("cannot open") != std::string::npos);
    const SceneError d = errorOf([] { readNffFile(kData); });
    CHECK(d.line == 0);
    CHECK(d.message.find("directory") != std::string::npos);
}

TEST_CASE("binary garbage never crashes the reader", "[nff]") {
    std::mt19937_64 gen(12345);
    int errors = 0;
    for (int i = 0; i < 500; ++i) {
        std::string junk(gen() % 300, '\0');
        for (char& c : junk) c = char(gen() & 0xff);
        try {
            parseNff(junk, "junk");
        } catch (const SceneError& e) {
            CHECK(e.line >= 1);
            CHECK(e.column >= 1);
            ++errors;
        }
    }
    CHECK(errors == 500);
}

TEST_CASE("mutated SPD files either parse or throw SceneError", "[nff]") {
    const std::string original = slurp(kScenes + "/balls1.nff");
    std::mt19937_64 gen(1986);
    const std::string alphabet = "0123456789.-+eE \n#svlfpbc\t";
    int parsed = 0, rejected = 0;
    for (int i = 0; i < 2000; ++i) {
        std::string text = original;
        const int edits = 1 + int(gen() % 4);
        for (int k = 0; k < edits; ++k) {
            const std::size_t at = gen() % text.size();
            switch (gen() % 4) {
                case 0: text[at] = alphabet[gen() % alphabet.size()]; break;
                case 1: text.erase(at, 1 + gen() % 8); break;
                case 2: text.insert(at, 1, alphabet[gen() % alphabet.size()]); break;
                default: text.resize(at); break;
            }
            if (text.empty()) text = "v";
        }
        try {
            const Scene s = parseNff(text, "mutant");
            for (const Sphere& sp : s.spheres) REQUIRE(sp.r > 0.0);
            ++parsed;
        } catch (const SceneError&) {
            ++rejected;
        }
    }
    // light mutations leave some files valid and break others: both paths ran
    CHECK(parsed > 0);
    CHECK(rejected > 0);
}
