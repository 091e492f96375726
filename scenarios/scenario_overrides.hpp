#pragma once
// Command-line overrides of a scenario document (gdnav scenario / montecarlo), applied to the scenario file BEFORE
// its generator runs, so they can set generator options, fix drawn values (the generator keeps what the file sets)
// or change any component parameter:
//   --set a.b.c=value     any key (value parsed as YAML; ~ removes the key), e.g. components.nav_att.variant=x,
//                         components.flight_physics.wind.speed_end_mps=0, generator.fixed.airspeed_ini_mps=30
//   --grade NAME          every sensor group's grade (gyr_grade and acc_grade of sensors_inertial, `grade` of the
//                         other sensors_* components), for the groups that have a grade NAME (the others keep theirs)
//   --grade GROUP=NAME    one group: gyroscopes, accelerometers, magnetometers, air_data, atmospheric, gnss
//   --variant NAME        navigation variant config/nav/variants/NAME.yaml: sets `variant: nav/variants/NAME.yaml` in
//                         the nav_att and nav_pos components (kVariantTypes); NAME may also be a path under config/
//   --variant COMP=NAME   the same in component COMP only
#include <filesystem>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace gdnav::scenario {

// Component types that take the navigation `variant` key.
inline const std::vector<std::string> kVariantTypes{"nav_att", "nav_pos"};

// "1" -> "paper1", "2" -> "paper2"; anything else unchanged.
std::string scenario_alias(const std::string& name_or_file);

struct Overrides {
    std::vector<std::string> sets;
    std::vector<std::string> grades;
    std::vector<std::string> variants;
    [[nodiscard]] bool empty() const { return sets.empty() && grades.empty() && variants.empty(); }
};

// Applies grades, then variants, then sets (so --set wins). Returns notes for the user (groups without the grade).
// Throws config::ConfigError on an unknown group, grade, variant or component.
std::vector<std::string> apply_overrides(YAML::Node& doc, const Overrides& o, const std::filesystem::path& config_dir);

}  // namespace gdnav::scenario
