#pragma once
// The DDS host's fault schedule (framework/faults/, docs/faults.md): read from the clock's CONFIGURE, grown by FAULTS
// (faults injected live); the scheduled kills and restarts of the host's own members.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dds/compat.hpp"
#include "dds/host/host_control.hpp"
#include "dds/host/host_inbox.hpp"
#include "framework/faults/fault_schedule.hpp"

namespace gdnav::dds::host {

class Faults {
public:
    using Rebuild = std::function<std::unique_ptr<framework::Component>(const std::string& name)>;
    // rebuild: creates a member anew for a restart (none: a restart of a member of this host is an error).
    explicit Faults(Rebuild rebuild) : rebuild_(std::move(rebuild)) {}

    // The clock's schedule (CONFIGURE). False when it cannot be read, or restarts a member of `locals` this host
    // cannot create anew.
    bool adopt(const std::string& yaml, const framework::RunInfo& ri, const std::vector<Local>& locals);
    // A longer schedule (a fault injected live): the index of its first new fault; none when it cannot be read.
    std::optional<std::size_t> adopt_live(const std::string& yaml, const framework::RunInfo& ri);

    [[nodiscard]] const framework::faults::FaultSchedule& schedule() const { return schedule_; }
    [[nodiscard]] bool empty() const { return schedule_.empty(); }

    // A scheduled kill or restart of member `l` at step k (called every step when the run has faults): a restart
    // replaces its object in `owned`; both are reported through `control`. Returns false when `l` is not stepped
    // at k.
    bool apply(Local& l, std::uint64_t k, std::vector<std::unique_ptr<framework::Component>>& owned,
               ControlPlane& control);

private:
    // Member `l` is created anew at step k (the old object goes, with its state).
    void restart(Local& l, std::uint64_t k, std::vector<std::unique_ptr<framework::Component>>& owned,
                 ControlPlane& control);

    Rebuild rebuild_;
    framework::faults::FaultSchedule schedule_;
};

}  // namespace gdnav::dds::host
