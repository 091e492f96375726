#include "framework/scenario_generator.hpp"

#include <map>

namespace gdnav::runtime {

namespace {
std::map<std::string, ScenarioGenerator>& table() {
    static std::map<std::string, ScenarioGenerator> t;
    return t;
}
}  // namespace

void register_scenario_generator(const std::string& name, ScenarioGenerator g) { table()[name] = std::move(g); }

const ScenarioGenerator* find_scenario_generator(const std::string& name) {
    auto it = table().find(name);
    return it == table().end() ? nullptr : &it->second;
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
    YAML::Node comps(YAML::NodeType::Map);
    if (doc["components"] && doc["components"].IsMap())
        for (const auto& c : doc["components"])
            if (c.second.IsMap() && c.second["type"]) comps[c.first.Scalar()]["type"] = YAML::Clone(c.second["type"]);
    bare["components"] = comps;
    YAML::Node drawn = (*g)(bare, seed, run_index, origin);
    drawn.remove("generator");
    return drawn;
}

std::vector<std::string> scenario_generator_names() {
    std::vector<std::string> v;
    for (const auto& [k, _] : table()) v.push_back(k);
    return v;
}

}  // namespace gdnav::runtime
