#include "launch/run_outcome.hpp"

#include <yaml-cpp/yaml.h>

namespace gdnav::launch {

ClockSummary read_clock_summary(const std::filesystem::path& file) {
    ClockSummary s;
    try {
        const YAML::Node doc = YAML::LoadFile(file.string());
        if (!doc.IsMap()) return s;
        if (doc["abort_reason"]) s.abort_reason = doc["abort_reason"].as<std::string>();
        if (const YAML::Node dead = doc["dead_members"]; dead && dead.IsSequence())
            for (const auto& d : dead) {
                DeadMember m;
                m.name = d["name"].as<std::string>("?");
                m.step = d["step"].as<std::uint64_t>(0);
                m.reason = d["reason"].as<std::string>("");
                s.dead.push_back(std::move(m));
            }
        s.found = true;
    } catch (const YAML::Exception&) {
        return ClockSummary{};
    }
    return s;
}

std::string failed_run_line(int code, const ClockSummary& summary, const std::vector<std::string>& failures) {
    std::string cause = summary.abort_reason;
    if (cause.empty() && !failures.empty()) cause = "process " + failures.front();
    if (cause.empty()) cause = "the clock ended with exit code " + std::to_string(code);
    return "run failed (exit code " + std::to_string(code) + "): " + cause;
}

std::string completed_run_line(const ClockSummary& summary, const std::vector<std::string>& failures,
                               const std::string& out_dir) {
    std::string without;
    auto add = [&without](const std::string& what) { without += (without.empty() ? "" : ", ") + what; };
    for (const auto& d : summary.dead)
        add(d.name + " (declared dead at step " + std::to_string(d.step) + (d.reason.empty() ? "" : ": " + d.reason) +
            ")");
    for (const auto& f : failures) {
        // A member the clock declared dead that also failed as a process is named once, with the clock's reason.
        bool named = false;
        for (const auto& d : summary.dead) named = named || f.rfind(d.name + " (", 0) == 0;
        if (!named) add(f);
    }
    return "run completed" + (without.empty() ? std::string() : " without: " + without) + "; results in " + out_dir;
}

}  // namespace gdnav::launch
