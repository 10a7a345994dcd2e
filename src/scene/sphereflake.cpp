#include "scene/sphereflake.h"
#include "scene/decimal.h"

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace rc {

namespace {

// The matrices and points of SPD's library: 4 x 4 matrices that multiply row vectors
// (x, y, z, w) from the right. SPD's PI, 3.141592653589793, is std::numbers::pi's double. Every expression below keeps SPD's
// order of operations, so that the doubles come out the same as SPD's, bit for bit
// (this file is compiled without floating-point contraction, see src/CMakeLists.txt). Its
// sin, cos, log, asin and acos are the C library's, not geometry/portable_math.h's: SPD's
// published numbers were printed with glibc's.

using Point4 = std::array<double, 4>;
using Matrix4 = std::array<std::array<double, 4>, 4>;

enum Axis { AxisX, AxisY, AxisZ };

Matrix4 identityMatrix() {
    Matrix4 m{};
    for (int i = 0; i < 4; ++i) m[i][i] = 1.0;
    return m;
}

/// Rotation by `angle` radians about a coordinate axis.
Matrix4 axisMatrix(Axis axis, double angle) {
    Matrix4 m{};
    const double c = std::cos(angle), s = std::sin(angle);
    const int i = axis == AxisX ? 1 : axis == AxisY ? 2 : 0;  // the two rows that turn
    const int j = axis == AxisX ? 2 : axis == AxisY ? 0 : 1;  // i -> j is a positive turn
    m[axis][axis] = 1.0;
    m[i][i] = c;
    m[j][j] = c;
    m[i][j] = s;
    m[j][i] = -s;
    m[3][3] = 1.0;
    return m;
}

/// Rotation by `angle` radians about the unit vector `a` (right-handed).
Matrix4 rotationMatrix(const Point4& a, double angle) {
    const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
    const double x = a[0], y = a[1], z = a[2];
    Matrix4 m{};
    m[0] = {x * x + (1.0 - x * x) * c, x * y * t + z * s, x * z * t - y * s, 0.0};
    m[1] = {x * y * t - z * s, y * y + (1.0 - y * y) * c, y * z * t + x * s, 0.0};
    m[2] = {x * z * t + y * s, y * z * t - x * s, z * z + (1.0 - z * z) * c, 0.0};
    m[3] = {0.0, 0.0, 0.0, 1.0};
    return m;
}

/// The row vector `v` times `m`.
Point4 transform(const Point4& v, const Matrix4& m) {
    Point4 r;
    for (int j = 0; j < 4; ++j) r[j] = v[0] * m[0][j] + v[1] * m[1][j] + v[2] * m[2][j] + v[3] * m[3][j];
    return r;
}

/// Scales (x, y, z) to unit length, unless it is zero.
void normalize(Point4& v) {
    const double d = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (d > 0.0)
        for (int i = 0; i < 3; ++i) v[i] /= d;
}

/// `v` as SPD prints it (`%g`: six significant digits) and the NFF reader reads it back.
double printed(double v) {
    char text[32];
    const std::size_t written = formatDecimal(v, 6, text, sizeof text);
    double back = v;
    parseDecimal(std::string_view(text, written), back);
    return back;
}

Vec3 printed(const Point4& p) { return Vec3(printed(p[0]), printed(p[1]), printed(p[2])); }

/// The Phong exponent SPD writes for a highlight whose intensity halves `degrees` off
/// the mirror direction; a highlight of no width prints as 100000.
double phongExponent(double degrees) {
    if (degrees <= 0.0) return 100000.0;
    return printed(std::log(0.5) / std::log(std::cos(degrees * std::numbers::pi / 180.0)));
}

// [sphereflake-children]
/// The directions of a sphere's 9 children, for a sphere whose own direction is +z:
/// a trio of directions, turned three times by 120 degrees about z.
std::array<Point4, 9> childDirections() {
    // The trio: three directions 90 degrees apart, tilted about (1, -1, 0) so that the
    // first rises 54.7 degrees above the equator and the other two lie on it
    const double d = 1.0 / std::sqrt(2.0);
    std::array<Point4, 3> trio = {Point4{d, d, 0.0, 0.0}, Point4{d, 0.0, -d, 0.0},
                                  Point4{0.0, d, -d, 0.0}};
    Point4 tilt = {1.0, -1.0, 0.0, 0.0};
    normalize(tilt);
    const Matrix4 tilted = rotationMatrix(tilt, std::asin(2.0 / std::sqrt(6.0)));
    for (Point4& p : trio) p = transform(p, tilted);

    // Three copies of the trio, 120 degrees apart
    std::array<Point4, 9> dirs;
    for (int set = 0; set < 3; ++set) {
        const Matrix4 turn = axisMatrix(AxisZ, set * 2.0 * std::numbers::pi / 3.0);
        for (int k = 0; k < 3; ++k) dirs[std::size_t(set * 3 + k)] = transform(trio[std::size_t(k)], turn);
    }
    return dirs;
}

/// Builds the flake depth first, as SPD prints it.
class Flake {
public:
    Flake(Scene& scene, int material) : scene_(scene), material_(material), dirs_(childDirections()) {}

    /// Adds the sphere `centre` (w: radius), then its children `depth` levels deep.
    /// `direction` points from the parent to this sphere (unit length up to rounding; w:
    /// the children's radius ratio).
    void add(int depth, const Point4& centre, const Point4& direction) {
        scene_.addSphere(Sphere{printed(centre), printed(centre[3])}, material_);
        if (depth == 0) return;

        // Turn +z into `direction`: about z x direction, by the angle between them
        Matrix4 turn;
        if (direction[2] >= 1.0) {
            turn = identityMatrix();
        } else if (direction[2] <= -1.0) {
            turn = axisMatrix(AxisY, std::numbers::pi);
        } else {
            const Point4 z = {0.0, 0.0, 1.0, 0.0};
            Point4 axis = {z[1] * direction[2] - z[2] * direction[1], z[2] * direction[0] - z[0] * direction[2],
                           z[0] * direction[1] - z[1] * direction[0], 0.0};
            normalize(axis);
            turn = rotationMatrix(axis, std::acos(z[0] * direction[0] + z[1] * direction[1] + z[2] * direction[2]));
        }

        // Each child touches this sphere: its centre lies r + r/3 away along its direction
        const double scale = centre[3] * (1.0 + direction[3]);
        for (const Point4& dir : dirs_) {
            Point4 child = transform(dir, turn);
            for (int i = 0; i < 3; ++i) child[std::size_t(i)] = child[std::size_t(i)] * scale + centre[std::size_t(i)];
            child[3] = centre[3] * direction[3];
            Point4 childDir;
            for (int i = 0; i < 3; ++i) childDir[std::size_t(i)] = (child[std::size_t(i)] - centre[std::size_t(i)]) / scale;
            childDir[3] = direction[3];
            add(depth - 1, child, childDir);
        }
    }

private:
    Scene& scene_;
    int material_;
    std::array<Point4, 9> dirs_;
};
// [sphereflake-children]

}  // namespace

long sphereflakeSpheres(int size) {
    long count = 0, level = 1;
    for (int i = 0; i <= size; ++i, level *= 9) count += level;
    return count;
}

Scene makeSphereflake(int size) {
    const std::string name = "balls:" + std::to_string(size);
    if (size < 1 || size > kMaxSphereflake)
        throw SceneError(name, 0, 0,
                         "bad balls size " + std::to_string(size) + ": expected 1 to " +
                             std::to_string(kMaxSphereflake));
    Scene s;
    s.name = name;
    // SPD's "UNC sky blue" and view: 45 degrees, 512 x 512
    s.background = Vec3(0.078, 0.361, 0.753);
    s.camera.from = Vec3(2.1, 1.3, 1.7);
    s.camera.at = Vec3(0.0);
    s.camera.up = Vec3(0.0, 0.0, 1.0);
    s.camera.angle = 45.0;
    s.camera.hither = 0.01;
    s.camera.width = s.camera.height = 512;
    for (const Vec3& p : {Vec3(4.0, 3.0, 2.0), Vec3(1.0, -4.0, 4.0), Vec3(-3.0, 1.0, 5.0)})
        s.lights.push_back(Light{p, Vec3(1.0), 0.0});

    // A beige diffuse ground square 24 wide, level with the bottom of the big sphere
    const double radius = 1.0;  // of the sphere that would hold the flake
    const int ground = s.addMaterial({Vec3(1.0, 0.75, 0.33), 0.8, 0.0, phongExponent(0.0), 0.0, 1.0});
    const double g = 12.0 * radius, h = -radius / 2.0;
    Polygon floor;
    if (auto err = makePolygon({Vec3(g, g, h), Vec3(-g, g, h), Vec3(-g, -g, h), Vec3(g, -g, h)}, {}, floor))
        throw SceneError(name, 0, 0, *err);
    s.addPolygon(std::move(floor), ground);

    // Mirrored spheres: half diffuse, half specular, highlights 37 degrees wide
    const int mirror = s.addMaterial({Vec3(1.0, 0.9, 0.7), 0.5, 0.5, phongExponent(37.0), 0.0, 1.0});
    s.spheres.reserve(std::size_t(sphereflakeSpheres(size)));
    s.objects.reserve(std::size_t(sphereflakeSpheres(size)) + 1);
    Flake(s, mirror).add(size, Point4{0.0, 0.0, 0.0, radius / 2.0}, Point4{0.0, 0.0, 1.0, 1.0 / 3.0});
    s.finalize();
    return s;
}

}  // namespace rc
