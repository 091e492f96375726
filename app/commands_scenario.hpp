#pragma once
// Shared by gdnav scenario and gdnav montecarlo: a scenario file (alias 1 / 2, name or path) with the command-line
// overrides (--set, --grade, --variant) applied, before its generator runs.
#include <filesystem>
#include <string>

#include <yaml-cpp/yaml.h>

#include "scenario_overrides.hpp"

namespace gdnav::cli {

struct ScenarioDocument {
    std::filesystem::path file;  // absolute path of the scenario file
    YAML::Node doc;              // its document with the overrides applied
};

ScenarioDocument load_scenario_document(const std::string& name_or_file, const scenario::Overrides& o);
// The document as YAML text (what gdnav run reads back).
std::string document_text(const YAML::Node& doc);

}  // namespace gdnav::cli
