#include "render/report.h"

#include "render/left_out.h"

namespace rc {

nlohmann::json countersJson(const Counters& n) {
    nlohmann::json j;
    j["rays"] = {{"primary", n.rays[int(RayKind::Primary)]},
                 {"shadow", n.rays[int(RayKind::Shadow)]},
                 {"reflection", n.rays[int(RayKind::Reflection)]},
                 {"refraction", n.rays[int(RayKind::Refraction)]},
                 {"total", n.totalRays()},
                 {"primary_hits", n.primaryHits}};
    j["intersection_tests"] = n.intersectionTests;
    j["complete_searches"] = n.completeSearches;
    j["cylinder_tests"] = n.cylinderTests;
    j["cone_tests"] = n.coneTests;
    nlohmann::json reasons = nlohmann::json::object();
    for (int r = 1; r < kMissReasons; ++r) reasons[std::string(toString(MissReason(r)))] = n.missReasons[r];
    j["cache"] = {{"hits", n.hits},
                  {"misses", n.misses},
                  {"miss_reasons", reasons},
                  {"deferrals", n.deferrals},
                  {"verify_disagreements", n.verifyDisagreements},
                  {"cylinders_built", n.cylindersBuilt},
                  {"cylinders_ruled_out", n.cylindersRuledOut},
                  {"cones_built", n.conesBuilt},
                  {"stepped_aside", n.steppedAside}};
    j["blocker_lists"] = {
        {"built", n.blockerListsBuilt},
        {"mean_length", n.blockerListsBuilt ? double(n.blockerListEntries) / double(n.blockerListsBuilt) : 0.0},
        {"max_length", n.blockerListMax},
        {"hull_tests", n.hullTests}};
    j["direction_lists"] = {
        {"searches", n.directionSearches},
        {"built", n.directionListsBuilt},
        {"mean_length", n.directionListsBuilt ? double(n.directionListEntries) / double(n.directionListsBuilt) : 0.0}};
    return j;
}

RenderSummary summarize(const RenderSession& s) {
    return {s.scene().name, s.options(), s.counters(), s.order().queuePeak(), s.order().regions(),
            s.cacheTree().size(), 1, leftOut(s.scene(), &s.options(), &s.counters())};
}

nlohmann::json statsJson(const RenderSummary& s, double seconds, const BeamTreeStats* beams) {
    nlohmann::json j = countersJson(s.counters);
    j["scene"] = s.scene;
    j["width"] = s.options.width;
    j["height"] = s.options.height;
    j["cache"]["strategy"] = std::string(toString(s.options.cache));
    j["order"] = std::string(toString(s.options.order));
    j["accel"] = std::string(toString(s.options.accel));
    j["threads"] = s.threads;
    j["seconds"] = seconds;
    j["depth"] = s.options.shading.maxDepth;
    j["cutoff"] = s.options.shading.cutoff;
    j["queue_peak"] = s.queuePeak;
    j["regions"] = s.regions;
    j["band"] = s.options.band;
    j["ray_tree_paths"] = s.paths;
    j["left_out"] = s.leftOut;
    if (beams) {
        j["beam_tree"] = {{"nodes", beams->nodes},
                          {"average_ray_tree_size", beams->averageRayTreeSize},
                          {"coherence", beams->coherence}};
        j["complete_searches_per_beam"] =
            beams->nodes ? double(s.counters.completeSearches) / double(beams->nodes) : 0.0;
    }
    return j;
}

}  // namespace rc
