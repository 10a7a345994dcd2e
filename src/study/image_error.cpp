#include "study/image_error.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "scene/random.h"

namespace rc {

namespace {
using Clock = std::chrono::steady_clock;

double clamp01(double v) { return v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v); }

double halton(int i, int base) {
    double f = 1.0, r = 0.0;
    for (; i > 0; i /= base) {
        f /= base;
        r += f * (i % base);
    }
    return r;
}
}  // namespace

LinearImage linearImage(const ImageAccumulator& image) {
    LinearImage out(std::size_t(image.width()) * image.height());
    for (std::size_t p = 0; p < out.size(); ++p) out[p] = image.value(int(p));
    return out;
}

double rmse(const LinearImage& a, const LinearImage& b) {
    if (a.size() != b.size() || a.empty()) return 0.0;
    double sum = 0.0;
    for (std::size_t p = 0; p < a.size(); ++p)
        for (int k = 0; k < 3; ++k) {
            const double d = clamp01(a[p][k]) - clamp01(b[p][k]);
            sum += d * d;
        }
    return std::sqrt(sum / (3.0 * double(a.size())));
}

double rmse(const ImageAccumulator& a, const LinearImage& b) {
    if (std::size_t(a.width()) * a.height() != b.size() || b.empty()) return 0.0;
    double sum = 0.0;
    for (std::size_t p = 0; p < b.size(); ++p) {
        const Vec3 v = a.value(int(p));
        for (int k = 0; k < 3; ++k) {
            const double d = clamp01(v[k]) - clamp01(b[p][k]);
            sum += d * d;
        }
    }
    return std::sqrt(sum / (3.0 * double(b.size())));
}

std::vector<ProgressPoint> traceProgress(std::shared_ptr<const Scene> scene, const RenderOptions& options,
                                         const LinearImage& final, std::int64_t totalSteps, int samples) {
    RenderSession session(std::move(scene), options);
    std::vector<ProgressPoint> out;
    out.push_back({0, 0.0, rmse(session.image(), final)});
    const std::int64_t every = std::max<std::int64_t>(1, totalSteps / std::max(1, samples));
    double seconds = 0.0;
    bool more = true;
    while (more) {
        // Render a slice of rays, timed; then measure, untimed
        const auto start = Clock::now();
        for (std::int64_t i = 0; i < every && (more = session.step()); ++i) {
        }
        seconds += std::chrono::duration<double>(Clock::now() - start).count();
        out.push_back({session.steps(), seconds, rmse(session.image(), final)});
    }
    return out;
}

std::vector<glm::dvec2> jitterOffsets(int n, std::uint64_t seed) {
    Random g(seed);
    const double sx = g.unit(), sy = g.unit();
    std::vector<glm::dvec2> out;
    for (int i = 0; i < n; ++i) {
        const double x = std::fmod(halton(i + 1, 2) + sx, 1.0), y = std::fmod(halton(i + 1, 3) + sy, 1.0);
        out.push_back({x - 0.5, y - 0.5});
    }
    return out;
}

std::vector<glm::dvec2> gridOffsets(int k) {
    std::vector<glm::dvec2> out;
    for (int j = 0; j < k; ++j)
        for (int i = 0; i < k; ++i) out.push_back({(i + 0.5) / k - 0.5, (j + 0.5) / k - 0.5});
    return out;
}

LinearImage averageImage(std::shared_ptr<const Scene> scene, RenderOptions options,
                         const std::vector<glm::dvec2>& offsets, double* seconds) {
    LinearImage sum;
    double total = 0.0;
    for (const glm::dvec2& off : offsets) {
        options.pixelOffset = off;
        RenderSession session(scene, options);
        const auto start = Clock::now();
        session.run();
        total += std::chrono::duration<double>(Clock::now() - start).count();
        const LinearImage img = linearImage(session.image());
        if (sum.empty()) sum.assign(img.size(), Vec3(0.0));
        for (std::size_t p = 0; p < img.size(); ++p) sum[p] += img[p];
    }
    for (Vec3& v : sum) v /= double(offsets.size());
    if (seconds) *seconds = total;
    return sum;
}

SuperSampler::SuperSampler(std::shared_ptr<const Scene> scene, RenderOptions options, const LinearImage& reference)
    : scene_(std::move(scene)), options_(options), reference_(reference) {}

void SuperSampler::add(const glm::dvec2& offset, bool last) {
    options_.pixelOffset = offset;
    RenderSession session(scene_, options_);
    const auto start = Clock::now();
    session.run();
    seconds_ += std::chrono::duration<double>(Clock::now() - start).count();
    const LinearImage img = linearImage(session.image());
    if (sum_.empty()) sum_.assign(img.size(), Vec3(0.0));
    for (std::size_t p = 0; p < img.size(); ++p) sum_[p] += img[p];
    const int spp = ++samples_;
    if ((spp & (spp - 1)) == 0 || last) {
        LinearImage mean = sum_;
        for (Vec3& v : mean) v /= double(spp);
        points_.push_back({spp, seconds_, rmse(mean, reference_)});
    }
}

std::vector<SupersamplePoint> superSample(std::shared_ptr<const Scene> scene, RenderOptions options,
                                          const std::vector<glm::dvec2>& offsets, const LinearImage& reference) {
    SuperSampler s(std::move(scene), options, reference);
    for (std::size_t i = 0; i < offsets.size(); ++i) s.add(offsets[i], i + 1 == offsets.size());
    return s.points();
}

}  // namespace rc
