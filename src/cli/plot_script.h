#pragma once
/// \file
/// \brief Charts drawn by the matplotlib scripts in scripts/plot_*.py, found through the
/// environment's RAYCACHE_SCRIPTS_DIR or the folder CMake was configured with.
#include <string>

namespace rc::cli {

/// A python3 that has matplotlib, or "".
std::string findPython();

/// Runs scripts/`script` on `csv`, writing the chart `out` with `title`. Returns 0; 1 when
/// there is no python3 with matplotlib; 2 when the script is missing or fails (with a
/// message on stderr).
int drawChart(const std::string& script, const std::string& csv, const std::string& out, const std::string& title);

/// Writes `table` (CSV text) to `csv` when one is named, and draws it into `plot` when one
/// is named, with scripts/`script` (`plot_NAME.py`; through a temporary raycache-NAME-PID.csv
/// when no CSV is named). Prints where each went. Returns the command's exit status: 0; 1
/// when the chart cannot be drawn (without matplotlib and a CSV to fall back on, 0).
int writeTableAndChart(const std::string& table, const std::string& csv, const std::string& plot,
                       const std::string& script, const std::string& title);

}  // namespace rc::cli
