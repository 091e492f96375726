#pragma once
// One host's slice of a deployment plan (`gdnav host --plan P --name H`, `gdnav run --plan P` for the clock's host;
// docs/deployment.md "Plans"). Every host resolves the same run from the plan (same scenario, seed, domain and
// overrides), writes the plan's Fast DDS XML (discovery from the plan, no hand-edited addresses) into its output
// directory, starts the discovery server(s) the plan puts on it, and starts and supervises its own members through
// the launcher.
#include <cstdint>
#include <filesystem>
#include <string>

#include "framework/registry.hpp"
#include "framework/run_config.hpp"
#include "launch/launcher.hpp"
#include "launch/plan/plan.hpp"
#include "launch/run_rewrites.hpp"

namespace gdnav::launch::deploy {

// The program that runs a discovery server (Debian's fastdds-tools).
inline constexpr const char* kDiscoveryServerProgram = "fast-discovery-server";

struct PlanHostRequest {
    std::string host;                     // empty: the host with the clock
    std::filesystem::path out;            // empty: out/plan/<host>
    std::uint64_t steps{0};               // > 0: override the number of steps
    launch::RunRewrites rw;               // --record only
    std::string log_level{"info"};
};

// What the host runs: the resolved run, the launcher's options for its slice, and one line naming what runs where.
struct PlanHostRun {
    framework::RunConfig rc;
    LaunchOptions lo;
    std::string summary;
};

// Resolves the host's run from the plan and `scenario_file` (the plan's scenario, resolved by the caller): creates
// the output directory and writes <out>/dds_plan.xml. Throws config::ConfigError (one line naming the plan, the
// host or the key) for a host not in the plan, a member placed on no host or two, or a discovery server program not
// on PATH.
PlanHostRun plan_host_run(const Plan& plan, const PlanHostRequest& req, const std::filesystem::path& scenario_file,
                          const framework::ComponentRegistry& reg);

// Absolute path of `program` on $PATH; throws config::ConfigError naming it when it is not there.
std::filesystem::path find_program(const std::string& program);

}  // namespace gdnav::launch::deploy
