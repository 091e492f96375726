#pragma once
// The lockstep clock (a runtime process, not a model): gathers the members, publishes the member table, starts the
// run when everybody is matched, sends Tick(k) and waits for every live member's StepDone(k), declares silent
// members dead (wall-clock heartbeat timeout), optionally paces to wall time, and ends the run with STOP or ABORT.
#include <memory>
#include <string>
#include <vector>

#include "dds/compat.hpp"
#include "framework/run_config.hpp"

namespace gdnav::dds {

struct ClockOptions {
    std::vector<std::string> members;  // barrier members expected before step 0 (default: all components)
    bool progress{true};               // log progress lines every ~2 s
    // Written to ("1") and closed once the clock owns its domain (no other clock heard while claiming it), so the
    // launcher starts the members only then; -1: none. A clock that refuses closes it unwritten (it exits).
    int ready_fd{-1};
};

class Clock {
public:
    Clock(const framework::RunConfig& rc, ClockOptions opt);
    ~Clock();
    int run();  // exit code (lockstep.hpp)

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace gdnav::dds
