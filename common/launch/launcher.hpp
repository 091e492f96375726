#pragma once
// `gdnav run`: validates the whole run config in-process (nothing starts on a bad config), writes the resolved
// config to <out>/run.yaml, then executes the run in the requested layout:
//   direct      — all components in this process, one thread, no transport;
//   composed    — a clock process + one process hosting every component (DDS between them);
//   distributed — a clock process + one process per component.
// It supervises the children (progress, exit codes, member deaths), forwards Ctrl-C, kills stragglers, and removes
// the Fast DDS shared-memory files its processes left behind.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "framework/registry.hpp"
#include "framework/run_config.hpp"

namespace gdnav::launch {

struct LaunchOptions {
    std::string layout{"distributed"};  // direct | composed | distributed
    std::filesystem::path exe;          // program to start for members (default: /proc/self/exe)
    std::string log_level{"info"};
    // One host's slice of a deployment plan (launch/plan/plan.hpp): start only these members (the others run on
    // other hosts) and the clock only when start_clock. Empty `only` = every member that is not external.
    std::vector<std::string> only;
    bool slice{false};
    bool start_clock{true};
    // Services started before the run and stopped after it (e.g. a Fast DDS discovery server): name, argv.
    std::vector<std::pair<std::string, std::vector<std::string>>> services;
};

// Returns the exit code of the run (0 = completed).
int launch_run(framework::RunConfig rc, const framework::ComponentRegistry& reg, const LaunchOptions& opt);

// Runs the direct layout in this process; returns steps/s through `steps_per_s` when not null.
int run_direct(const framework::RunConfig& rc, const framework::ComponentRegistry& reg, bool progress,
               double* steps_per_s = nullptr);

}  // namespace gdnav::launch
