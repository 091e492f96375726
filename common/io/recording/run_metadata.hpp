#pragma once
// The "gdnav.run" metadata record of a recording (record_file.hpp): what a viewer shows about the run.
#include <map>
#include <string>

#include "framework/component.hpp"

namespace gdnav::io::recording {

// Keys: gdnav_version, seed, run_index, steps, t0_s, dt_s, step_ns, log_time_epoch (how log times map to
// simulated time), and, from the run's configuration `run_yaml` (the resolved run.yaml, "" when unknown):
// config_digest (FNV-1a 64 of its bytes), layout, mission (the guidance mission's name, which names the paper
// scenario, seed and run), faults (number of scheduled faults) and components.NAME.KEY for every member's type and
// scalar choices that select models (aircraft, suite, grade, gyr_grade, acc_grade, tuning, variant, init_mode, autopilot).
std::map<std::string, std::string> run_metadata(const framework::RunInfo& run, const std::string& run_yaml);

}  // namespace gdnav::io::recording
