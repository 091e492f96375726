#include "dds/host/host_phase.hpp"

#include <algorithm>

#include <spdlog/spdlog.h>

#include "framework/lockstep.hpp"

namespace gdnav::dds::host {

RunPhase::RunPhase(const framework::RunConfig& rc)
    : timing_{rc.info, rc.window_steps, rc.done_every(), rc.member_timeout_s},
      announce_timeout_s_(rc.startup_timeout_s + (rc.external.empty() ? 0.0 : rc.join_timeout_s)) {}

void RunPhase::adopt_timing(const msg::RunControl& c) {
    framework::RunInfo& ri = timing_.ri;
    if (c.steps() != ri.steps || c.dt_s() != ri.dt_s || c.t0_s() != ri.t0_s)
        spdlog::debug("timing from the clock: {} steps of {} s from t0 = {} s", c.steps(), c.dt_s(), c.t0_s());
    ri.steps = c.steps();
    ri.dt_s = c.dt_s();
    ri.t0_s = c.t0_s();
    timing_.window_steps = c.window_steps();
    ri.seed = c.seed();
    timing_.done_every = std::max<std::uint64_t>(c.done_every(), 1);
    timing_.member_timeout_s = c.member_timeout_s();
}

bool RunPhase::clock_alive(double now, int& code) const {
    const double silent_s = now - last_clock_s_;
    if (phase_ == Phase::Announce || (phase_ != Phase::Running && !have_tick_)) {
        if (phase_ == Phase::Announce && now - start_s_ > announce_timeout_s_) {
            spdlog::error("no clock: no member table from the clock '{}' within {:.1f} s", framework::kClockName,
                          announce_timeout_s_);
            code = framework::kExitStartup;
            return false;
        }
        if (phase_ != Phase::Announce && silent_s > timing_.member_timeout_s) {
            spdlog::error("lost the clock '{}': no Tick or heartbeat for {:.1f} s before the start",
                          framework::kClockName, silent_s);
            code = framework::kExitLostClock;
            return false;
        }
    } else if (silent_s > timing_.member_timeout_s) {
        spdlog::error("lost the clock '{}': no Tick or heartbeat for {:.1f} s (last Tick: step {})",
                      framework::kClockName, silent_s, tick_step_);
        code = framework::kExitLostClock;
        return false;
    }
    return true;
}

}  // namespace gdnav::dds::host
