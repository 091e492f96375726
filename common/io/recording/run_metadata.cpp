#include "io/recording/run_metadata.hpp"

#include <yaml-cpp/yaml.h>

#include <cstdio>

#include "io/recording/record_file.hpp"

namespace gdnav::io::recording {

namespace {
std::string exact(double v) {
    char buf[40];
    std::snprintf(buf, sizeof(buf), "%.17g", v);
    return buf;
}
}  // namespace

std::map<std::string, std::string> run_metadata(const framework::RunInfo& run, const std::string& run_yaml) {
    std::map<std::string, std::string> m{
        {"gdnav_version", GDNAV_VERSION},
        {"seed", std::to_string(run.seed)},
        {"run_index", std::to_string(run.run_index)},
        {"steps", std::to_string(run.steps)},
        {"t0_s", exact(run.t0_s)},
        {"dt_s", exact(run.dt_s)},
        {"step_ns", std::to_string(step_ns(run.dt_s))},
        {"log_time_epoch", "t0_s: log_time = publish_time = step * step_ns ns; t_s = t0_s + step * dt_s"},
    };
    if (run_yaml.empty()) return m;
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(run_yaml.data());
    m["config_digest"] = digest_hex(fnv1a(kFnvBasis, bytes, run_yaml.size()));
    const std::string layout_tag = "(layout ";
    if (const auto at = run_yaml.find(layout_tag); at != std::string::npos && at < run_yaml.find('\n'))
        m["layout"] = run_yaml.substr(at + layout_tag.size(), run_yaml.find(')', at) - at - layout_tag.size());
    try {
        const YAML::Node root = YAML::Load(run_yaml);
        if (const YAML::Node f = root["faults"]; f && f.IsSequence()) m["faults"] = std::to_string(f.size());
        for (const auto& kv : root["components"]) {
            const std::string name = kv.first.as<std::string>();
            if (!kv.second.IsMap()) continue;
            for (const char* key : {"type", "aircraft", "suite", "grade", "gyr_grade", "acc_grade", "tuning", "variant",
                                    "init_mode", "autopilot"})
                if (const YAML::Node v = kv.second[key]; v && v.IsScalar())
                    m["components." + name + "." + key] = v.as<std::string>();
                else if (v && v.IsMap())
                    m["components." + name + "." + key] = YAML::Dump(v);
            if (const YAML::Node mission = kv.second["mission"]; mission && mission.IsMap() && mission["name"])
                m["mission"] = mission["name"].as<std::string>();
        }
    } catch (const YAML::Exception&) {
        m["config_error"] = "run.yaml does not parse";
    }
    return m;
}

}  // namespace gdnav::io::recording
