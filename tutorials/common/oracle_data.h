#pragma once
// The checks grade against data, not code. An oracle that computes the graded function
// (a golden-section search, roots by bisection, a brute-force labelling) is itself an
// answer, so it is not shipped: the instructor's build runs the oracles
// (tutorials/instructor/oracles/) under each check and records every answer they give,
// keyed by the case's inputs, in the tutorial's oracle_data.txt; a check reads its
// expected values from there.
//
// Each tutorial's oracles.cpp holds its oracles' entries: a function of the case's inputs
// that returns
//     TUTORIAL_ORACLE(type, Key("name") << inputs..., instructor's computation)
// which is the recorded value in the student's build (the computation is not compiled,
// only named) and, in the instructor's recording program (TUTORIAL_RECORD), the
// computation, recorded. The data file: one line per case, `<key> <value>`, the key a
// 64-bit hash of the oracle's name and its inputs' bytes, the value at full precision
// (%.17g, which reads back as the same double).
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/ray.h"
#include "geometry/sphere.h"

namespace tutorial {

/// The inputs of one oracle case, hashed (FNV-1a over the name and the inputs' bytes).
class Key {
public:
    explicit Key(const char* oracle) : name_(oracle) { bytes(oracle, std::char_traits<char>::length(oracle)); }
    Key& operator<<(double x) { return bytes(&x, sizeof x); }
    Key& operator<<(int x) { return bytes(&x, sizeof x); }
    Key& operator<<(const rc::Vec3& v) { return *this << v.x << v.y << v.z; }
    Key& operator<<(const rc::Sphere& s) { return *this << s.c << s.r; }
    Key& operator<<(const rc::Ray& r) { return *this << r.o << r.d; }
    template <class T>
    Key& operator<<(const std::vector<T>& v) {
        *this << int(v.size());
        for (const T& x : v) *this << x;
        return *this;
    }
    std::uint64_t hash() const { return hash_; }
    const char* name() const { return name_; }

private:
    Key& bytes(const void* p, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) hash_ = (hash_ ^ static_cast<const unsigned char*>(p)[i]) * 1099511628211ull;
        return *this;
    }
    const char* name_;
    std::uint64_t hash_ = 14695981039346656037ull;
};

/// The value recorded for `key` in the data file `path` (read once); throws, naming the
/// oracle, when the file has none (a case the instructor's run never met).
std::string expectedText(const std::string& path, const Key& key);
/// Instructor's recording: `text` is the value for `key` (written at exit to
/// $TUTORIAL_ORACLE_RECORD).
void recordText(const Key& key, const std::string& text);

// Values as text, at full precision
std::string encode(double x);
std::string encode(const std::vector<double>& v);
void decode(const std::string& text, double& x);
void decode(const std::string& text, std::vector<double>& v);

template <class T>
T expected(const std::string& path, const Key& key) {
    T value;
    decode(expectedText(path, key), value);
    return value;
}
template <class T>
T recorded(const Key& key, const T& value) {
    recordText(key, encode(value));
    return value;
}

}  // namespace tutorial

#ifdef TUTORIAL_RECORD
#define TUTORIAL_ORACLE(type, key, computed) tutorial::recorded<type>(key, computed)
#else
#define TUTORIAL_ORACLE(type, key, computed) tutorial::expected<type>(TUTORIAL_DIR "/oracle_data.txt", key)
#endif
