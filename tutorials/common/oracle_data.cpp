// The expected values of the checks (oracle_data.h): read from a tutorial's data file, or
// recorded by the instructor's run of the oracles.
#include "oracle_data.h"

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

namespace tutorial {

namespace {
std::string hex(std::uint64_t h) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", (unsigned long long)h);
    return buf;
}

// Every value recorded by this run, written at exit in key order
struct Recording {
    std::map<std::uint64_t, std::string> values;
    ~Recording() {
        if (values.empty()) return;
        const char* path = std::getenv("TUTORIAL_ORACLE_RECORD");
        if (!path) {
            std::fprintf(stderr, "oracle data: %zu values recorded, but TUTORIAL_ORACLE_RECORD names no file\n",
                         values.size());
            return;
        }
        std::ofstream out(path);
        out << "# Expected values of this tutorial's check: <key> <value>, written by the instructor's\n"
               "# oracles (cmake --build build --target tutorial-data). Do not edit.\n";
        for (const auto& [key, text] : values) out << hex(key) << ' ' << text << '\n';
    }
};
Recording recording;
}  // namespace

std::string expectedText(const std::string& path, const Key& key) {
    static std::map<std::string, std::map<std::uint64_t, std::string>> files;
    auto [it, fresh] = files.try_emplace(path);
    if (fresh) {
        std::ifstream in(path);
        if (!in) throw std::runtime_error(path + ": the check's expected values cannot be read");
        std::string line;
        while (std::getline(in, line)) {
            if (line.empty() || line[0] == '#') continue;
            const std::size_t space = line.find(' ');
            it->second[std::strtoull(line.substr(0, space).c_str(), nullptr, 16)] = line.substr(space + 1);
        }
    }
    const auto found = it->second.find(key.hash());
    if (found == it->second.end())
        throw std::runtime_error(path + " holds no expected value for this case of `" + key.name() + "` (key " +
                                 hex(key.hash()) +
                                 "): its inputs are not the reference's (code of an earlier tutorial that differs "
                                 "from the reference?), or the data is out of date");
    return found->second;
}

void recordText(const Key& key, const std::string& text) {
    auto [it, fresh] = recording.values.try_emplace(key.hash(), text);
    if (!fresh && it->second != text)
        throw std::logic_error(std::string("oracle data: two values for one key of `") + key.name() + "`: " +
                               it->second + " and " + text);
}

std::string encode(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}
std::string encode(const std::vector<double>& v) {
    std::string out;
    for (double x : v) out += (out.empty() ? "" : " ") + encode(x);
    return out;
}
void decode(const std::string& text, double& x) { x = std::strtod(text.c_str(), nullptr); }
void decode(const std::string& text, std::vector<double>& v) {
    v.clear();
    const char* p = text.c_str();
    for (char* end = nullptr;; p = end) {
        const double x = std::strtod(p, &end);
        if (end == p) break;
        v.push_back(x);
    }
}

}  // namespace tutorial
