#include "scenario_overrides.hpp"

#include <array>

#include "config/config.hpp"
#include "scenario_yaml.hpp"

namespace gdnav::scenario {

namespace fs = std::filesystem;
using config::ConfigError;

namespace {

struct Group {
    const char* group;  // folder under config/sensors
    const char* type;   // component type
    const char* key;    // key in the component section
};
constexpr std::array<Group, 6> kGroups{{
    {"gyroscopes", "sensors_inertial", "gyr_grade"},
    {"accelerometers", "sensors_inertial", "acc_grade"},
    {"magnetometers", "sensors_magnetic", "grade"},
    {"air_data", "sensors_air", "grade"},
    {"atmospheric", "sensors_atmospheric", "grade"},
    {"gnss", "sensors_gnss", "grade"},
}};

std::vector<std::string> components_of_type(const YAML::Node& doc, const std::string& type) {
    std::vector<std::string> v;
    const YAML::Node comps = doc["components"];
    if (!comps || !comps.IsMap()) return v;
    for (const auto& kv : comps)
        if (kv.second.IsMap() && kv.second["type"] && kv.second["type"].Scalar() == type)
            v.push_back(kv.first.as<std::string>());
    return v;
}

std::string known_files(const fs::path& dir) {
    std::string s;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.path().extension() == ".yaml") s += (s.empty() ? "" : ", ") + e.path().stem().string();
    return s;
}

void set_in_type(YAML::Node& doc, const std::string& type, const std::string& key, const std::string& value) {
    for (const auto& c : components_of_type(doc, type)) apply_set(doc, "components." + c + "." + key + "=" + value);
}

}  // namespace

std::string scenario_alias(const std::string& s) {
    if (s == "1") return "paper1";
    if (s == "2") return "paper2";
    return s;
}

std::vector<std::string> apply_overrides(YAML::Node& doc, const Overrides& o, const fs::path& config_dir) {
    std::vector<std::string> notes;
    for (const auto& g : o.grades) {
        const auto eq = g.find('=');
        const std::string name = eq == std::string::npos ? g : g.substr(eq + 1);
        const std::string only = eq == std::string::npos ? std::string() : g.substr(0, eq);
        if (name.empty()) throw ConfigError("--grade '" + g + "': empty grade name");
        bool group_found = only.empty(), applied = false;
        for (const Group& gr : kGroups) {
            if (!only.empty() && only != gr.group) continue;
            group_found = true;
            const fs::path file = config_dir / "sensors" / gr.group / (name + ".yaml");
            if (!fs::exists(file)) {
                if (!only.empty())
                    throw ConfigError("--grade '" + g + "': no grade '" + name + "' for " + gr.group + " (available: " +
                                      known_files(config_dir / "sensors" / gr.group) + ")");
                notes.push_back(std::string(gr.group) + " has no grade '" + name + "': keeping the suite's");
                continue;
            }
            set_in_type(doc, gr.type, gr.key, name);
            applied = true;
        }
        if (!group_found)
            throw ConfigError("--grade '" + g + "': unknown sensor group '" + only +
                              "' (gyroscopes, accelerometers, magnetometers, air_data, atmospheric, gnss)");
        if (!applied && only.empty()) throw ConfigError("--grade '" + g + "': no sensor group has a grade '" + name + "'");
    }
    for (const auto& v : o.variants) {
        const auto eq = v.find('=');
        const std::string name = eq == std::string::npos ? v : v.substr(eq + 1);
        // NAME -> nav/variants/NAME.yaml (the nav components' `variant` key holds a file relative to config/).
        const bool is_path = name.find('/') != std::string::npos || fs::path(name).extension() == ".yaml";
        const std::string file = is_path ? name : "nav/variants/" + name + ".yaml";
        if (!fs::exists(config_dir / file))
            throw ConfigError("--variant '" + v + "': no variant file " + (config_dir / file).string() +
                              " (available: " + known_files(config_dir / "nav" / "variants") + ")");
        if (eq != std::string::npos) {
            const std::string comp = v.substr(0, eq);
            if (!doc["components"] || !doc["components"][comp])
                throw ConfigError("--variant '" + v + "': the scenario has no component '" + comp + "'");
            apply_set(doc, "components." + comp + ".variant=" + file);
        } else {
            bool any = false;
            for (const auto& t : kVariantTypes) {
                any = any || !components_of_type(doc, t).empty();
                set_in_type(doc, t, "variant", file);
            }
            if (!any) throw ConfigError("--variant '" + v + "': the scenario has no nav_att or nav_pos component");
        }
    }
    for (const auto& s : o.sets) apply_set(doc, s);
    return notes;
}

}  // namespace gdnav::scenario
