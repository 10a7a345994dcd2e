#pragma once
/// \file
/// \brief Per-pixel sums in fixed point, so the order of additions cannot change a bit.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/ray.h"

namespace rc {

/// Accumulates ray contributions per pixel. Integer addition is associative, so any
/// visiting order (scanline, breadth-first, progressive, threads) sums to the same
/// image, bit for bit; 2^-32 is far below an 8-bit step.
class ImageAccumulator {
public:
    static constexpr double kScale = 4294967296.0;  // 2^32

    ImageAccumulator(int width = 0, int height = 0) : ImageAccumulator(width, height, 0, height) {}
    /// An image that holds only scanlines [rowBegin, rowEnd) (a thread's block); the other
    /// pixels read as black and take no memory.
    ImageAccumulator(int width, int height, int rowBegin, int rowEnd)
        : width_(width), height_(height), first_(std::size_t(width) * std::size_t(rowBegin)),
          sum_(std::size_t(width) * std::size_t(rowEnd - rowBegin) * 3, 0) {}

    // [accumulate]
    /// Adds a contribution to a pixel, rounded to a multiple of 2^-32.
    void add(int pixel, const Vec3& c) {
        for (int k = 0; k < 3; ++k) {
            std::int64_t& sum = sum_[(std::size_t(pixel) - first_) * 3 + k];
            sum = saturatingAdd(sum, toFixed(c[k]));
        }
    }
    /// The pixel's sum so far.
    Vec3 value(int pixel) const {
        const std::size_t i = (std::size_t(pixel) - first_) * 3;  // wraps below first_
        if (i >= sum_.size()) return Vec3(0.0);
        const std::int64_t* p = &sum_[i];
        return Vec3(double(p[0]), double(p[1]), double(p[2])) / kScale;
    }
    // [accumulate]
    /// Adds another image of the same size, pixel by pixel (the rows both hold).
    ImageAccumulator& operator+=(const ImageAccumulator& o) {
        const std::size_t begin = std::max(first_, o.first_) * 3;
        const std::size_t end = std::min(first_ * 3 + sum_.size(), o.first_ * 3 + o.sum_.size());
        for (std::size_t i = begin; i < end; ++i)
            sum_[i - first_ * 3] = saturatingAdd(sum_[i - first_ * 3], o.sum_[i - o.first_ * 3]);
        return *this;
    }
    /// The 8-bit RGB image, clamped to [0, 1].
    std::vector<std::uint8_t> rgb8() const;
    /// The same bytes written in place: pixel p's at out[p * stride], out[p * stride + 1]
    /// and out[p * stride + 2] (stride 4: into an RGBA picture, its alpha left alone).
    void rgb8Into(std::uint8_t* out, std::size_t stride) const;
    /// The same for pixels [begin, end) only, pixel `begin`'s bytes at out[0] (a band of
    /// rows, for a caller that keeps no image-sized buffer).
    void rgb8Into(std::uint8_t* out, std::size_t stride, int begin, int end) const;
    int width() const { return width_; }
    int height() const { return height_; }
    /// The fixed-point sums of the rows held, 3 per pixel, row after row: what a
    /// checkpoint of a render keeps (ImageSnapshot).
    std::span<const std::int64_t> sums() const { return sum_; }
    std::span<std::int64_t> sums() { return sum_; }

    /// Largest magnitude of one contribution: far brighter than white, small enough that
    /// 2^11 of them fit the sum. Scenes with absurd light (colours of 1e100) reach it.
    static constexpr double kMaxContribution = 1048576.0;  // 2^20
    /// One contribution in fixed point: NaN counts as 0, magnitudes are clamped.
    static std::int64_t toFixed(double v) {
        if (std::isnan(v)) return 0;
        v = v < -kMaxContribution ? -kMaxContribution : (v > kMaxContribution ? kMaxContribution : v);
        // std::llround (half away from zero), inline: |v| * 2^32 <= 2^52 truncates exactly,
        // and the fraction left, a - r, is exact
        const double a = std::fabs(v * kScale);
        std::int64_t r = std::int64_t(a);
        // (added, not branched on: the fraction is a coin toss the processor would guess)
        r += std::int64_t(a - double(r) >= 0.5);
        return v < 0.0 ? -r : r;
    }
    /// Sums stop at the int64 limits instead of overflowing (undefined behaviour). With
    /// contributions of one sign, as shading's are, that is still independent of order.
    static std::int64_t saturatingAdd(std::int64_t a, std::int64_t b) {
        std::int64_t r = 0;
        if (__builtin_add_overflow(a, b, &r)) return b > 0 ? INT64_MAX : INT64_MIN;
        return r;
    }

private:
    int width_, height_;
    std::size_t first_ = 0;  ///< the first pixel held
    std::vector<std::int64_t> sum_;
};

/// 8-bit value of one channel.
inline std::uint8_t toByte(double v) {
    const double c = v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v);
    return std::uint8_t(std::floor(c * 255.0 + 0.5));
}

inline void ImageAccumulator::rgb8Into(std::uint8_t* out, std::size_t stride, int begin, int end) const {
    for (int p = begin; p < end; ++p) {
        const Vec3 v = value(p);
        for (int k = 0; k < 3; ++k) out[std::size_t(p - begin) * stride + std::size_t(k)] = toByte(v[k]);
    }
}

inline void ImageAccumulator::rgb8Into(std::uint8_t* out, std::size_t stride) const {
    rgb8Into(out, stride, 0, width_ * height_);
}

inline std::vector<std::uint8_t> ImageAccumulator::rgb8() const {
    std::vector<std::uint8_t> out(std::size_t(width_) * height_ * 3);
    rgb8Into(out.data(), 3);
    return out;
}

}  // namespace rc
