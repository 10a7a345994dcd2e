#pragma once
/// \file
/// \brief The one random-number generator of RayCache: portable doubles.
#include <cstdint>
#include <random>

namespace rc {

/// Random doubles that are the same on every machine: std::mt19937_64's output sequence is
/// fixed by the standard, and the conversion to [0, 1) is done here (53 bits), never by a
/// library distribution (whose algorithm the standard leaves open).
class Random {
public:
    explicit Random(std::uint64_t seed) : gen_(seed) {}
    /// Uniform in [0, 1), 53 random bits.
    double unit() { return double(gen_() >> 11) * 0x1.0p-53; }
    double operator()() { return unit(); }
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    /// Uniform in {0, ..., n - 1}.
    int index(int n) { return int(unit() * n); }

private:
    std::mt19937_64 gen_;
};

}  // namespace rc
