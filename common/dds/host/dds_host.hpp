#pragma once
// DDS host: runs one or more components in one process (distributed = one each, composed = several), talking to
// the clock and to the other members over Fast DDS, following the lockstep protocol of lockstep.hpp.
// Inputs are kept in per-port inboxes indexed by step, so arrival order never matters. The fault schedule comes
// with the clock's CONFIGURE (framework/faults/): inputs pass through it, killed members are not stepped.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dds/compat.hpp"
#include "framework/component.hpp"
#include "framework/run_config.hpp"

namespace gdnav::dds {

struct HostOptions {
    bool free_running{false};  // members of this host are not in the barrier; inputs use the latest samples
    // Creates a member anew when a scheduled fault restarts it (RunConfig::build_one); without it, a restart
    // of a member of this host ends the host with an error.
    std::function<std::unique_ptr<framework::Component>(const std::string& name)> rebuild;
    // Come back into a running run after this member was declared dead (gdnav component --rejoin): announce with
    // "rejoin", and start at the step the clock assigns (docs/faults.md, "Rejoin").
    bool rejoin{false};
};

class DdsHost {
public:
    DdsHost(const framework::RunConfig& rc, std::vector<std::unique_ptr<framework::Component>> members,
            HostOptions opt = {});
    ~DdsHost();
    DdsHost(const DdsHost&) = delete;
    DdsHost& operator=(const DdsHost&) = delete;
    // Runs until STOP / ABORT / lost clock / signal. Returns the process exit code (lockstep.hpp).
    int run();
    // After run(): the reason the clock gave with its ABORT ("" when it sent none).
    [[nodiscard]] std::string abort_reason() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace gdnav::dds
