#pragma once
/// \file
/// \brief The subcommands of `raycache`. Each lives in a file of its own and registers itself
/// with an add...Command function that main() calls.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "render/render_session.h"

namespace rc::cli {

/// A registered subcommand and what runs when it is chosen (returns the exit code).
struct Command {
    CLI::App* app = nullptr;
    std::function<int()> run;
};
using Commands = std::vector<Command>;

/// Options shared by every subcommand that renders.
struct RenderFlags {
    int width = 0, height = 0, depth = 5, band = kAutoBand;
    double cutoff = 0.0;
    std::string cache = "none", order = "scanline", accel = "linear";
    std::uint64_t seed = 1986;
    bool verify = false;
    Sampling sampling;  ///< distributed ray tracing (seed: `seed`)
    std::string sampleEntries = "shared";
    /// Adds --width --height --depth --cutoff --band --seed; with `cacheAndOrder` also
    /// --cache and --order.
    void addTo(CLI::App* c, bool cacheAndOrder);
    /// Adds distributed ray tracing's options: --light-radius --shadow-samples --gloss
    /// --gloss-samples --sample-entries, and with `spp` also --spp. Bad values (negative,
    /// not finite, over a limit) stop the command line with exit 2, before any work.
    void addSamplingTo(CLI::App* c, bool spp);
    RenderOptions options() const;
};

/// Writes to stderr one warning per polygon the reader skipped (Scene::skipped), each
/// `raycache: warning: file:line:column: message`.
void warnSkipped(const Scene& scene);

/// Checks that an output file can be written (its folder exists and is writable, and it
/// is not a folder) when the command line is parsed, before any work.
const CLI::Validator& outputFile();

void addRenderCommand(CLI::App& app, Commands& out);
void addInfoCommand(CLI::App& app, Commands& out);
void addScenesCommand(CLI::App& app, Commands& out);
void addTable1Command(CLI::App& app, Commands& out);
void addBenchCommand(CLI::App& app, Commands& out);
void addStabilityCommand(CLI::App& app, Commands& out);
void addConvergenceCommand(CLI::App& app, Commands& out);
void addCoherenceCommand(CLI::App& app, Commands& out);
void addListCommand(CLI::App& app, Commands& out);

/// The names of every registered cache, order and (exact) complete search: `--cache`,
/// `--order` and `--accel` take one of them.
std::vector<std::string> cacheNames();
std::vector<std::string> orderNames();
std::vector<std::string> searchNames();

}  // namespace rc::cli
