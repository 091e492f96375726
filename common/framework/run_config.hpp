#pragma once
// The run configuration: one YAML document that every process of a run reads (the launcher writes the resolved
// file to <out>/run.yaml). Layout:
//
//   run:
//     seed: 1                  # master seed
//     run_index: 0             # index inside a batch
//     steps: 2000              # number of 10-ms steps (or duration_s)
//     dt_s: 0.01
//     t0_s: 0.0                # simulated time of step 0
//     realtime: 0              # pacing factor (0 = as fast as possible, 1 = wall time, 10 = 10x)
//     member_timeout_s: 1.5    # wall-clock silence after which a member (or the clock) is declared dead
//     startup_timeout_s: 30    # wall-clock wait for all members before step 0
//     stall_timeout_s: 60      # wall-clock wait without progress while everybody is alive
//     window_steps: 16         # how far a member may run ahead of the last Tick (0 = strict lockstep;
//                              # forced to 0 when realtime > 0); see docs/runtime.md
//     observer_nice: 19        # nice value (0..19) of a process that hosts only observers (e.g. the live bridge in
//                              # the distributed layout); 0 = the run's own priority (dds/process/process_priority.hpp)
//     essential: [plant]       # members whose loss aborts the run
//     external: [nav_att]      # members run outside gdnav (not started; waited for; docs/protocol.md)
//     join_timeout_s: 60       # wall-clock wait for external members before step 0
//     domain_id: 0             # DDS domain (the launcher picks a free one when absent)
//     dds_profile: dds/gdnav_profiles.xml   # relative to the config directory
//     security: pki/             # DDS Security directory (gdnav pki init; relative to the working directory);
//                                # absent = no security (dds/security/security.hpp, docs/deployment.md)
//     out_dir: out/run
//   components:
//     plant: {type: chain_plant, ...component parameters...}
//   faults:                    # optional: scheduled faults (framework/faults/fault_schedule.hpp, docs/faults.md)
//     - {at_s: 10, until_s: 20, target: plant, kind: drop}
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "framework/compat.hpp"
#include "framework/component.hpp"
#include "framework/faults/fault_schedule.hpp"
#include "framework/registry.hpp"

namespace gdnav::framework {

// Where config/ lives: $GDNAV_CONFIG_DIR, else the source tree's config/ (compiled in).
std::filesystem::path config_dir();
// Resolves a scenario name (config/scenarios/<name>.yaml) or a file path.
std::filesystem::path resolve_scenario(const std::string& name_or_file);

struct RunOverrides {
    std::optional<std::uint64_t> seed;
    std::optional<std::uint64_t> run_index;
    std::optional<std::string> out_dir;
    std::optional<double> realtime;
    std::optional<int> domain_id;
    std::optional<std::uint64_t> steps;
    std::optional<std::vector<std::string>> external;
    std::optional<double> join_timeout_s;
    std::optional<std::filesystem::path> faults_file;  // replaces the `faults:` list (gdnav run --faults)
    std::optional<std::filesystem::path> security;     // run.security (gdnav run --security DIR)
};

struct MemberSpec {
    std::string name;
    std::string type;
    config::Config cfg;  // the component's section (its "type" key already read)
};

// The longest run.member_timeout_s accepted. The DDS profiles' participant lease is longer, so that DDS never drops a
// silent participant before gdnav's own timeouts judge it (config/dds/gdnav_profiles.xml).
inline constexpr double kMemberTimeoutMax_s = 60.0;

class RunConfig {
public:
    static RunConfig load(const std::filesystem::path& file, const RunOverrides& overrides = {});
    static RunConfig parse(const std::string& yaml_text, const std::string& origin, const RunOverrides& o = {});

    // Creates and configures every component (validating its section). Throws ConfigError on the first problem.
    [[nodiscard]] std::vector<std::unique_ptr<Component>> build(const ComponentRegistry& reg,
                                                                const std::vector<std::string>& only = {}) const;
    // Creates and configures one component (as build() does): a member restarted by a fault starts like this.
    [[nodiscard]] std::unique_ptr<Component> build_one(const ComponentRegistry& reg, const std::string& name) const;
    // The resolved document (overrides applied) as YAML text.
    [[nodiscard]] std::string to_yaml() const;

    RunInfo info;
    double realtime{0.0};
    double member_timeout_s{1.5};
    double startup_timeout_s{30.0};
    double stall_timeout_s{60.0};
    std::uint64_t window_steps{64};
    int observer_nice{19};  // nice value of a process hosting only observers (0: unchanged)
    // StepDone is reported every done_every steps (window/2, at least 1).
    [[nodiscard]] std::uint64_t done_every() const { return window_steps / 2 > 0 ? window_steps / 2 : 1; }
    int domain_id{0};
    bool domain_given{false};
    std::vector<std::string> essential;
    // Members that gdnav does not start: external participants announcing themselves under these names. A name may
    // be a configured component (replaced) or a new member.
    std::vector<std::string> external;
    double join_timeout_s{60.0};
    [[nodiscard]] bool is_external(const std::string& name) const;
    // Barrier members the clock waits for: configured components and external members, in that order.
    [[nodiscard]] std::vector<std::string> member_names() const;
    std::filesystem::path dds_profile;
    // DDS Security directory (absolute; empty = security off). Every participant of the run uses it.
    std::filesystem::path security_dir;
    std::string out_dir;
    std::vector<MemberSpec> members;  // in file order
    faults::FaultSchedule faults;     // top-level `faults:` list (docs/faults.md)
    std::string faults_origin;        // the file it came from (the run config, or gdnav run --faults FILE)
    std::string origin;

private:
    YAML::Node root_;
};

}  // namespace gdnav::framework
