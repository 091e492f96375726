#pragma once
// YAML helpers of the scenario generators and of the command-line overrides.
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace gdnav::scenario {

// Shortest decimal text that reads back to the same double (std::to_chars), e.g. 29.13, -72, 1.5e-05.
std::string shortest(double v);
// A scalar node holding shortest(v).
YAML::Node number(double v);
// An angle in radians as degrees; values within 1e-9 deg of an integer print as that integer (integer draws).
YAML::Node degrees(double rad);
// An empty mapping written in flow style ({a: 1, b: 2}): the guidance operations' channels and triggers.
YAML::Node flow_map();
// A guidance channel {mode: MODE, KEY: VALUE}.
YAML::Node channel(const char* mode, const char* key, const YAML::Node& value);
// A guidance trigger {trigger: elapsed, dt_s: DT}: the operation ends DT seconds after it began.
YAML::Node until_elapsed(double dt_s);

// Adds to `target` every key of `drawn` it does not have, recursively into mappings both have. Keys the template
// already sets are kept (the scenario file overrides the draw); their paths are appended to `kept`.
void fill_missing(YAML::Node target, const YAML::Node& drawn, const std::string& path, std::vector<std::string>* kept);

// Applies one override "a.b.c=value" to `doc`: `value` is parsed as YAML (a number, a word, a flow mapping or
// sequence); `~` or `null` removes the key. Path segments name mapping keys, or indices into sequences. Missing
// mappings on the way are created. Throws config::ConfigError on a malformed assignment.
void apply_set(YAML::Node& doc, const std::string& assignment);

}  // namespace gdnav::scenario
