/// \file
/// \brief raycache: the command-line tool. Renders scenes with any cache and order, reports what
/// each did, and reproduces the paper's Table 1.
#include <iostream>
#include <new>

#include <CLI/CLI.hpp>

#include "cli/commands.h"
#include "render/output_files.h"
#include "scene/scene.h"

int main(int argc, char** argv) {
    CLI::App app{"RayCache: caching and breadth-first search to speed up ray tracing (Hanrahan 1986)"};
    app.require_subcommand(1);
    rc::cli::Commands commands;
    rc::cli::addRenderCommand(app, commands);
    rc::cli::addInfoCommand(app, commands);
    rc::cli::addScenesCommand(app, commands);
    rc::cli::addTable1Command(app, commands);
    rc::cli::addBenchCommand(app, commands);
    rc::cli::addStabilityCommand(app, commands);
    rc::cli::addConvergenceCommand(app, commands);
    rc::cli::addCoherenceCommand(app, commands);
    rc::cli::addListCommand(app, commands);
    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        app.exit(e);
        return 2;  // every bad flag or value: exit code 2
    }
    try {
        for (const rc::cli::Command& c : commands)
            if (*c.app) return c.run();
        return 2;
    } catch (const rc::SceneError& e) {
        std::cerr << "raycache: " << e.what() << "\n";
        return 2;
    } catch (const rc::OutputError& e) {  // an output that cannot be written
        std::cerr << "raycache: " << e.what() << "\n";
        return 2;
    } catch (const std::invalid_argument& e) {
        std::cerr << "raycache: " << e.what() << "\n";
        return 2;
    } catch (const std::bad_alloc&) {
        // The scene or the image needs more memory than there is (or than ulimit -v allows)
        std::cerr << "raycache: out of memory: the scene or the image is too large for the memory available\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "raycache: " << e.what() << "\n";
        return 1;
    }
}
