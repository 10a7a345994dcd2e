#include "cli/plot_script.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "render/output_files.h"

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

int writeTableAndChart(const std::string& table, const std::string& csv, const std::string& plot,
                       const std::string& script, const std::string& title) {
    std::string csvPath = csv;
    if (csvPath.empty() && !plot.empty()) {
        const std::string name = std::filesystem::path(script).stem().string().substr(std::string("plot_").size());
        csvPath = (std::filesystem::temp_directory_path() / ("raycache-" + name + "-" + std::to_string(getpid()) + ".csv")).string();
    }
    if (!csvPath.empty()) writeTextFile(csvPath, table);
    if (!csv.empty()) std::printf("\nCSV: %s\n", csv.c_str());
    if (plot.empty()) return 0;
    const int rc = drawChart(script, csvPath, plot, title);
    if (csv.empty() && rc != 1) std::filesystem::remove(csvPath);
    if (rc == 1) return csv.empty() ? 1 : 0;  // no matplotlib: the CSV has the numbers
    if (rc != 0) return 1;
    std::printf("chart: %s\n", plot.c_str());
    return 0;
}

}  // namespace rc::cli
