#pragma once
// Scenario generators: a run config may name a generator instead of (or besides) spelling out every parameter:
//
//   generator: {name: paper_scenario1, ...generator options...}
//   run: {...}
//   components: {...}           # template sections; the generator fills in the drawn values
//
// Before the config is validated, the generator named there is called with the whole document, the master seed and
// the run index, and returns the complete document (without the `generator` key). Generators draw from their own
// streams (seed, run index, "scenario/..."), so run i of a batch is a pure function of (seed, i).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "framework/compat.hpp"

namespace gdnav::framework {

// Returns the completed document. Throws config::ConfigError on bad generator options (name the key and origin).
using ScenarioGenerator =
    std::function<YAML::Node(const YAML::Node& doc, std::uint64_t seed, std::uint64_t run_index, const std::string& origin)>;

void register_scenario_generator(const std::string& name, ScenarioGenerator g);
// nullptr when unknown.
const ScenarioGenerator* find_scenario_generator(const std::string& name);
std::vector<std::string> scenario_generator_names();

// What the document's generator draws for run (seed, run_index), apart from any component setting: the generator
// applied to the document's `generator` section and its components reduced to their `type`, so that two runs fly the
// same mission exactly when their drawn scenarios are equal, whatever filter variant, sensor grade or member they
// run. A Null node when the document names no generator (nothing is drawn). Throws as the generator does.
YAML::Node drawn_scenario(const YAML::Node& doc, std::uint64_t seed, std::uint64_t run_index, const std::string& origin);

}  // namespace gdnav::framework
