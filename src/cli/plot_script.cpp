#include "cli/plot_script.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace rc::cli {

namespace {
std::filesystem::path scriptsDir() {
    const char* env = std::getenv("RAYCACHE_SCRIPTS_DIR");
    return env && *env ? env : RAYCACHE_SCRIPTS_DIR;
}

std::string shellQuoted(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}
}  // namespace

std::string findPython() {
    for (const char* py : {"/usr/bin/python3", "python3"}) {
        const std::string cmd = std::string(py) + " -c 'import matplotlib' >/dev/null 2>&1";
        if (std::system(cmd.c_str()) == 0) return py;
    }
    return "";
}

int drawChart(const std::string& script, const std::string& csv, const std::string& out, const std::string& title) {
    const std::string python = findPython();
    if (python.empty()) {
        std::fprintf(stderr, "raycache: the chart needs python3 with matplotlib (Debian: python3-matplotlib); "
                             "the numbers are in %s\n", csv.c_str());
        return 1;
    }
    const std::filesystem::path path = scriptsDir() / script;
    if (!std::filesystem::is_regular_file(path)) {
        std::fprintf(stderr, "raycache: the chart script %s is missing (set RAYCACHE_SCRIPTS_DIR); the numbers are in %s\n",
                     path.c_str(), csv.c_str());
        return 2;
    }
    const std::string cmd = python + " " + shellQuoted(path.string()) + " " + shellQuoted(csv) + " " +
                            shellQuoted(out) + " " + shellQuoted(title);
    if (std::system(cmd.c_str()) != 0) {
        std::fprintf(stderr, "raycache: drawing the chart failed\n");
        return 2;
    }
    return 0;
}

}  // namespace rc::cli
