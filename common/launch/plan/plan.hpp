#pragma once
// A deployment plan (deploy/plans/*.yaml, docs/deployment.md "Plans"): which hosts take part in a run, their
// addresses, which members each host runs and how, the discovery mode and the DDS profile. Validated on load like
// every config: one error naming the file and key.
//
//   scenario: paper2            # scenario name or YAML file (as gdnav run --scenario); relative to the plan's folder
//   seed: 1                     # optional (the scenario's own otherwise)
//   domain_id: 7                # fixed: every host must use the same domain
//   discovery: peers            # multicast | peers | server
//   server: {host: a, port: 11811, backup: b}   # discovery: server (backup optional)
//   dds_profile: dds/gdnav_profiles.xml          # base QoS (config dir); discovery settings are added to it
//   hosts:
//     a: {address: 10.231.0.1, clock: true, process: composed,
//         members: [flight_physics, sensors_inertial, ...]}
//     b: {address: 10.231.0.2, members: [nav_air, ...]}
//   run: {startup_timeout_s: 60, member_timeout_s: 3}   # optional: keys merged into the scenario's run section
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace gdnav::launch::deploy {

struct PlanHost {
    std::string name;
    std::string address;               // IPv4 address other hosts reach it at
    bool clock{false};                 // runs the lockstep clock
    std::string process{"composed"};   // composed: one process for its members; distributed: one per member
    std::vector<std::string> members;  // configured members of the scenario (or `recorder`)
};

struct Plan {
    std::filesystem::path file;
    std::string scenario;  // as given (resolved by the caller)
    std::optional<std::uint64_t> seed;
    int domain_id{0};
    std::string discovery{"peers"};  // multicast | peers | server
    std::string server_host, backup_host;
    int server_port{11811};
    std::filesystem::path dds_profile;  // absolute
    std::vector<PlanHost> hosts;        // file order
    YAML::Node run_overrides;           // mapping merged into the run section (may be null)

    static Plan load(const std::filesystem::path& file);
    [[nodiscard]] const PlanHost& host(const std::string& name) const;  // throws ConfigError naming the plan
    [[nodiscard]] const PlanHost& clock_host() const;
    // Checks the plan against the members of the resolved run: every member on exactly one host.
    void check_members(const std::vector<std::string>& run_members, const std::vector<std::string>& external) const;
};

// The Fast DDS XML for every host of the plan: the base profile with the plan's discovery (multicast: unchanged;
// peers: every host's address as an initial peer; server: clients of the plan's discovery server(s)).
std::string plan_profile_xml(const Plan& plan);
// GUID prefix of discovery server `id` as `fastdds discovery -i ID` makes it (44.53.<id>.5f.45.50.52.4f.53.49.4d.41).
std::string server_prefix(int id);

}  // namespace gdnav::launch::deploy
