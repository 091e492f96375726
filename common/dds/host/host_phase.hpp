#pragma once
// Where the DDS host is in the run, as the clock's control messages tell it (docs/protocol.md §3): the run's timing
// (from the local config, replaced by the clock's CONFIGURE), the phase, the clock's last Tick and how long the clock
// has been silent.
#include <cstdint>

#include "dds/compat.hpp"
#include "framework/component.hpp"
#include "framework/run_config.hpp"
#include "msgs/messages.hpp"

namespace gdnav::dds::host {

// The run's timing: from the local config, replaced by the clock's CONFIGURE (protocol version >= 1), so a member
// that knows only the domain and the run id (an external client) steps exactly like a built-in one.
struct RunTiming {
    framework::RunInfo ri;
    std::uint64_t window_steps{0};
    std::uint64_t done_every{1};
    double member_timeout_s{0.0};
};

class RunPhase {
public:
    // Announce: waiting for the member table; Matching: configured, matching the peers it implies; Ready: matched,
    // waiting for Ticks; Running: Ticks came after READY.
    enum class Phase { Announce, Matching, Ready, Running };

    explicit RunPhase(const framework::RunConfig& rc);

    [[nodiscard]] Phase phase() const { return phase_; }
    [[nodiscard]] const RunTiming& timing() const { return timing_; }

    // The timing of the clock's CONFIGURE (before the host's parts take the member table).
    void adopt_timing(const msg::RunControl& c);
    // The host took the member table at `now`: it matches its peers; the clock is alive now (a member started long
    // before it must not count that wait as silence).
    void joined(double now) {
        phase_ = Phase::Matching;
        last_clock_s_ = now;
    }
    // Matching is done: READY.
    void matched() { phase_ = Phase::Ready; }
    // A Tick of this run at `now`, for step `step`. A rejoining member sees Ticks while matching.
    void tick(std::uint64_t step, double now) {
        last_clock_s_ = now;
        if (!have_tick_ || step > tick_step_) tick_step_ = step;
        have_tick_ = true;
        if (phase_ == Phase::Ready) phase_ = Phase::Running;
    }
    // A heartbeat of the clock of this run at `now`.
    void heard_clock(double now) { last_clock_s_ = now; }

    // Starts the clock's silence timer (the main loop's start).
    void start(double now) {
        start_s_ = now;
        last_clock_s_ = now;
    }
    // The host's loop was not scheduled for `stall_s` (own_stall_s): that time is not the clock's silence.
    void discount_own_stall(double stall_s) { last_clock_s_ += stall_s; }
    // False when the clock is missing or lost (then `code` is the exit code).
    bool clock_alive(double now, int& code) const;

    // Whether step k may be computed now: Ticks have started, k is within the window and within the run.
    [[nodiscard]] bool may_step(std::uint64_t k) const {
        return have_tick_ && k <= tick_step_ + timing_.window_steps && k < timing_.ri.steps;
    }

private:
    RunTiming timing_;
    // How long to wait for the member table: start-up, plus the join time of external members.
    double announce_timeout_s_{0.0};
    Phase phase_{Phase::Announce};
    std::uint64_t tick_step_{0};
    bool have_tick_{false};
    double last_clock_s_{0.0};
    double start_s_{0.0};
};

}  // namespace gdnav::dds::host
