#pragma once
// The subcommands of `raycache` and the options they take.
#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "render/render_session.h"

namespace rc::cli {

/// Options shared by every subcommand that renders.
struct RenderFlags {
    int width = 0, height = 0, depth = 5, band = 16;
    double cutoff = 0.0;
    std::string cache = "none", order = "scanline";
    std::uint64_t seed = 1986;
    bool verify = false;
    RenderOptions options() const;
};

/// Registers the subcommands and runs the one that was chosen.
class Commands {
public:
    void addTo(CLI::App& app);
    int run();

private:
    int render();
    int info();
    int scenes();
    int table1();

    CLI::App* renderCmd_ = nullptr;
    CLI::App* infoCmd_ = nullptr;
    CLI::App* scenesCmd_ = nullptr;
    CLI::App* table1Cmd_ = nullptr;

    std::string scene_;
    std::string out_, stats_;
    bool quiet_ = false;
    RenderFlags flags_;

    std::vector<int> sizes_{3, 4, 5};
    int repeat_ = 3;
    std::string csv_;
};

}  // namespace rc::cli
