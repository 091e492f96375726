#pragma once
// DDS host: runs one or more components in one process (distributed = one each, composed = several), talking to
// the clock and to the other members over Fast DDS, following the lockstep protocol of lockstep.hpp.
// Inputs are kept in per-port inboxes indexed by step, so arrival order never matters.
#include <memory>
#include <vector>

#include "runtime/component.hpp"
#include "runtime/run_config.hpp"

namespace gdnav::runtime {

struct HostOptions {
    bool free_running{false};  // members of this host are not in the barrier; inputs use the latest samples
};

class DdsHost {
public:
    DdsHost(const RunConfig& rc, std::vector<std::unique_ptr<Component>> members, HostOptions opt = {});
    ~DdsHost();
    DdsHost(const DdsHost&) = delete;
    DdsHost& operator=(const DdsHost&) = delete;
    // Runs until STOP / ABORT / lost clock / signal. Returns the process exit code (lockstep.hpp).
    int run();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace gdnav::runtime
