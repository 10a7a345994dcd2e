#pragma once
/// \file
/// \brief The one random-number generator of RayCache: portable doubles, as a sequence
/// (Random) or as a pure function of a key (hashed numbers, for distributed ray tracing).
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

// [hashed-random]
/// Mixes `value` into the key `key`: SplitMix64's finalizer (Steele, Lea and Flood 2014)
/// over the sum, a bijection on 64 bits. Keys made by chaining mixKey are a pure function
/// of what went in, in order: no state, so any visiting order and any thread draws the
/// same numbers for the same key.
constexpr std::uint64_t mixKey(std::uint64_t key, std::uint64_t value) {
    std::uint64_t z = key + 0x9E3779B97F4A7C15ull * (value + 1);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/// The `k`-th uniform number in [0, 1) of key `key` (53 bits).
constexpr double hashedUnit(std::uint64_t key, std::uint64_t k) {
    return double(mixKey(key, k) >> 11) * 0x1.0p-53;
}
// [hashed-random]

}  // namespace rc
