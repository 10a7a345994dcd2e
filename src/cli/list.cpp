/// \file
/// \brief `raycache list caches|orders|searches|overlays|scenes [--json]`: what the registries
/// hold, for people and for scripts (tests/web/web_hashes.py reads `list caches --json`).
#include <cstdio>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "view/registry_listing.h"

namespace rc::cli {

namespace {

struct ListArgs {
    std::string what;
    bool json = false;
};

}  // namespace

void addListCommand(CLI::App& app, Commands& out) {
    auto a = std::make_shared<ListArgs>();
    CLI::App* c = app.add_subcommand("list", "list what can be chosen by name: caches, orders, searches, "
                                             "overlays or built-in scenes");
    c->add_option("what", a->what, "caches | orders | searches | overlays | scenes")
        ->required()
        ->check(CLI::IsMember({"caches", "orders", "searches", "overlays", "scenes"}));
    c->add_flag("--json", a->json, "as a JSON array of {name, description, ...}");
    out.push_back({c, [a] {
        const nlohmann::json j = registryListing(a->what);
        if (a->json) {
            std::printf("%s\n", j.dump(2).c_str());
            return 0;
        }
        for (const nlohmann::json& e : j)
            std::printf("%-12s %s\n", e["name"].get<std::string>().c_str(),
                        e["description"].get<std::string>().c_str());
        return 0;
    }});
}

}  // namespace rc::cli
