#include "framework/run_members.hpp"

#include <algorithm>
#include <filesystem>
#include <vector>

#include "config/config.hpp"
#include "framework/lockstep.hpp"

namespace gdnav::runtime {

using config::Config;

namespace {

// One `python:` entry -> the component section that replaces (or adds) member `name`.
YAML::Node python_component(const Config& entry, const YAML::Node& replaced) {
    const Config py = entry.child("python");
    const std::string file = py.get_string("file");
    const std::string cls = py.get_string("class");
    py.finish();
    entry.finish();
    if (file.empty()) py.fail("file", "empty (the Python file that defines the member's class)");
    if (cls.empty()) py.fail("class", "empty (the name of the member's class in the file)");
    YAML::Node c(YAML::NodeType::Map);
    c["type"] = kPythonMemberType;
    // Absolute, so that every process of the run (started in the same working directory) and run.yaml name it.
    c["file"] = std::filesystem::absolute(file).lexically_normal().string();
    c["class"] = cls;
    if (replaced && replaced.IsMap() && replaced["type"] && replaced["type"].IsScalar())
        c["replaces"] = replaced["type"].as<std::string>();
    return c;
}

}  // namespace

void apply_inprocess_members(YAML::Node& root, const std::string& origin) {
    YAML::Node run = root["run"];
    if (!run || !run.IsMap() || !run["members"]) return;
    const Config top = Config::wrap(root, origin);
    const Config members = top.child("run").child("members");
    std::vector<std::string> external;
    if (run["external"] && run["external"].IsSequence())
        for (const auto& e : run["external"]) external.push_back(e.as<std::string>());
    std::vector<std::string> hosted;
    for (const auto& name : members.keys()) {
        const Config entry = members.child(name);
        if (!entry.has("python")) continue;  // a member of another kind
        if (name.empty() || name.size() > 63 || name.find_first_of(", \t") != std::string::npos)
            members.fail(name, "not a member name (1-63 characters, no commas or spaces)");
        if (name == kClockName) members.fail(name, "'clock' is the lockstep clock and cannot be replaced");
        if (std::find(external.begin(), external.end(), name) != external.end())
            members.fail(name, "also listed in run.external: a member is either hosted here or external");
        YAML::Node comps = root["components"];
        if (!comps || !comps.IsMap()) top.fail("components", "missing (required)");
        comps[name] = python_component(entry, comps[name]);
        hosted.push_back(name);
    }
    for (const auto& name : hosted) run["members"].remove(name);
    if (run["members"].size() == 0) run.remove("members");
}

}  // namespace gdnav::runtime
