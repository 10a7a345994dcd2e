#include "search/embree_search.h"

#include <algorithm>
#include <cfloat>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include <embree3/rtcore.h>

namespace rc {

namespace {
// The intersection context, extended with where the ray starts
struct OriginContext {
    RTCIntersectContext context;
    const Query* query;
    const std::vector<int>* sphereIds;
    const std::vector<int>* triangleIds;
    unsigned sphereGeometry;
};

void skipOrigin(const RTCFilterFunctionNArguments* args) {
    const auto* ctx = reinterpret_cast<const OriginContext*>(args->context);
    const int origin = ctx->query->origin.object;
    if (origin < 0) return;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned geom = RTCHitN_geomID(args->hit, args->N, i);
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        const bool sphere = geom == ctx->sphereGeometry;
        const int id = sphere ? (*ctx->sphereIds)[prim] : (*ctx->triangleIds)[prim];
        if (id != origin) continue;
        // Leaving the surface it starts on: no hit; entering a sphere: only the far side
        const float t = RTCRayN_tfar(args->ray, args->N, i);
        const Vec3& o = ctx->query->ray.o;
        const double size = std::max({std::abs(o.x), std::abs(o.y), std::abs(o.z)});
        if (!sphere || !ctx->query->origin.inside || t < 1e-4f * float(1.0 + size))
            args->valid[i] = 0;
    }
}
}  // namespace

struct EmbreeSearch::Impl {
    const Scene& scene;
    RTCDevice device = nullptr;
    RTCScene rtc = nullptr;
    unsigned sphereGeometry = RTC_INVALID_GEOMETRY_ID;
    std::vector<int> sphereIds, triangleIds;
    explicit Impl(const Scene& s) : scene(s) {}
};

namespace {
/// Embree is given spheres and fans of triangles: a cone or a concave polygon has no fan.
const Scene& supported(const Scene& scene) {
    const auto cones = scene.cones.size();
    const auto concave = std::count_if(scene.polygons.begin(), scene.polygons.end(),
                                       [](const Polygon& p) { return !p.convex; });
    if (cones > 0 || concave > 0)
        throw std::invalid_argument("--accel embree takes spheres and convex polygons only; this scene has " +
                                    std::to_string(cones) + " cones or cylinders (c) and " +
                                    std::to_string(concave) + " concave polygons: use --accel bvh");
    return scene;
}
}  // namespace

EmbreeSearch::EmbreeSearch(const Scene& scene)
    : CompleteSearch(supported(scene)), impl_(std::make_unique<Impl>(scene)) {
    Impl& m = *impl_;
    m.device = rtcNewDevice("threads=1");
    if (!m.device) throw std::runtime_error("embree: cannot create a device");
    m.rtc = rtcNewScene(m.device);
    rtcSetSceneBuildQuality(m.rtc, RTC_BUILD_QUALITY_HIGH);
    // [embree-build]
    std::vector<float> spheres;
    std::vector<float> vertices;
    std::vector<unsigned> triangles;
    for (int id = 0; id < scene.size(); ++id) {
        const Object& o = scene.objects[id];
        if (o.shape == Shape::Sphere) {
            const Sphere& s = scene.spheres[o.index];
            spheres.insert(spheres.end(), {float(s.c.x), float(s.c.y), float(s.c.z), float(s.r)});
            m.sphereIds.push_back(id);
        } else {
            const Polygon& p = scene.polygons[o.index];
            const unsigned base = unsigned(vertices.size() / 3);
            for (const Vec3& v : p.vertices) vertices.insert(vertices.end(), {float(v.x), float(v.y), float(v.z)});
            for (unsigned k = 1; k + 1 < p.vertices.size(); ++k) {
                triangles.insert(triangles.end(), {base, base + k, base + k + 1});
                m.triangleIds.push_back(id);
            }
        }
    }
    if (!spheres.empty()) {
        RTCGeometry g = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
        float* buf = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                                                                 4 * sizeof(float), spheres.size() / 4));
        std::memcpy(buf, spheres.data(), spheres.size() * sizeof(float));
        rtcSetGeometryIntersectFilterFunction(g, skipOrigin);
        rtcCommitGeometry(g);
        m.sphereGeometry = rtcAttachGeometry(m.rtc, g);
        rtcReleaseGeometry(g);
    }
    if (!triangles.empty()) {
        RTCGeometry g = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_TRIANGLE);
        float* vb = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                3 * sizeof(float), vertices.size() / 3));
        std::memcpy(vb, vertices.data(), vertices.size() * sizeof(float));
        unsigned* ib = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                      3 * sizeof(unsigned), triangles.size() / 3));
        std::memcpy(ib, triangles.data(), triangles.size() * sizeof(unsigned));
        rtcSetGeometryIntersectFilterFunction(g, skipOrigin);
        rtcCommitGeometry(g);
        rtcAttachGeometry(m.rtc, g);
        rtcReleaseGeometry(g);
    }
    rtcCommitScene(m.rtc);
    // [embree-build]
}

EmbreeSearch::~EmbreeSearch() {
    if (impl_->rtc) rtcReleaseScene(impl_->rtc);
    if (impl_->device) rtcReleaseDevice(impl_->device);
}

Answer EmbreeSearch::nearest(const Query& q, Counters&) const {
    const Impl& m = *impl_;
    OriginContext ctx;
    rtcInitIntersectContext(&ctx.context);
    ctx.query = &q;
    ctx.sphereIds = &m.sphereIds;
    ctx.triangleIds = &m.triangleIds;
    ctx.sphereGeometry = m.sphereGeometry;
    RTCRayHit rh{};
    rh.ray.org_x = float(q.ray.o.x);
    rh.ray.org_y = float(q.ray.o.y);
    rh.ray.org_z = float(q.ray.o.z);
    rh.ray.dir_x = float(q.ray.d.x);
    rh.ray.dir_y = float(q.ray.d.y);
    rh.ray.dir_z = float(q.ray.d.z);
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = q.tmax < double(FLT_MAX) ? float(q.tmax) : FLT_MAX;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(m.rtc, &ctx.context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
    const int id = rh.hit.geomID == m.sphereGeometry ? m.sphereIds[rh.hit.primID] : m.triangleIds[rh.hit.primID];
    // The distance in double precision on the object Embree found
    const double t = m.scene.intersect(q.ray, id, q.origin);
    return {id, t < q.tmax ? t : double(rh.ray.tfar)};
}

bool embreeAvailable() { return true; }

}  // namespace rc
