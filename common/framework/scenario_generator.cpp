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

std::vector<std::string> scenario_generator_names() {
    std::vector<std::string> v;
    for (const auto& [k, _] : table()) v.push_back(k);
    return v;
}

}  // namespace gdnav::runtime
