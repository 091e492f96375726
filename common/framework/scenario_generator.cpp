#include "framework/scenario_generator.hpp"

#include <map>

namespace gdnav::framework {

namespace {
std::map<std::string, ScenarioGenerator>& generators() {
    static std::map<std::string, ScenarioGenerator> t;
    return t;
}
}  // namespace

void register_scenario_generator(const std::string& name, ScenarioGenerator g) { generators()[name] = std::move(g); }

const ScenarioGenerator* find_scenario_generator(const std::string& name) {
    auto it = generators().find(name);
    return it == generators().end() ? nullptr : &it->second;
}

YAML::Node drawn_scenario(const YAML::Node& doc, std::uint64_t seed, std::uint64_t run_index,
                          const std::string& origin) {
    const YAML::Node gen = doc["generator"];
    if (!gen || !gen["name"]) return YAML::Node();
    const ScenarioGenerator* g = find_scenario_generator(gen["name"].as<std::string>());
    if (!g) return YAML::Node();
    YAML::Node bare;
    bare["generator"] = YAML::Clone(gen);
    bare["run"]["seed"] = seed;
    bare["run"]["run_index"] = run_index;
    // The run's timing, which a generator may move (a calibration pattern starts the run earlier). Kept in the
    // drawn scenario only where the generator changed it, so that scenarios whose generator leaves it alone draw
    // what they drew before (gdnav compare matches batches by this text's SHA-256).
    static const char* const kTiming[] = {"t0_s", "dt_s", "duration_s", "steps"};
    const YAML::Node run = doc["run"];
    std::map<std::string, std::string> given;
    for (const char* k : kTiming)
        if (run && run.IsMap() && run[k] && run[k].IsScalar()) {
            bare["run"][k] = YAML::Clone(run[k]);
            given[k] = run[k].Scalar();
        }
    YAML::Node comps(YAML::NodeType::Map);
    if (doc["components"] && doc["components"].IsMap())
        for (const auto& c : doc["components"])
            if (c.second.IsMap() && c.second["type"]) comps[c.first.Scalar()]["type"] = YAML::Clone(c.second["type"]);
    bare["components"] = comps;
    YAML::Node drawn = (*g)(bare, seed, run_index, origin);
    drawn.remove("generator");
    if (YAML::Node r = drawn["run"]; r && r.IsMap())
        for (const auto& [k, v] : given)
            if (r[k] && r[k].IsScalar() && r[k].Scalar() == v) r.remove(k);
    return drawn;
}

std::vector<std::string> scenario_generator_names() {
    std::vector<std::string> v;
    for (const auto& [k, _] : generators()) v.push_back(k);
    return v;
}

}  // namespace gdnav::framework
