#pragma once
// Evaluation of an operation's trigger on the navigation estimate (docs/guidance-control.md, "Guidance").
//
// Crossing triggers (pressure_altitude, altitude, path_angle, airspeed): at the start of the operation the sign
// s0 = [measured >= target] is stored; the trigger fires at the first evaluation where [measured >= target] != s0.
// Bearing triggers (bearing, heading): d = wrap(measured - target) in (-pi, pi]. Only |d| <= 90 deg counts: beyond
// it the trigger is inactive and re-arms (stores the sign of d) at the first later evaluation back within 90 deg,
// so a crossing of the opposite bearing is never taken for a crossing of the target. Fires when sign(d) changes.
// Time triggers are level triggers: time fires when t + 1e-10 >= value, elapsed when t + 1e-10 - t_start >= value.
//   (The reference stores the initial sign for these too, so an operation started after its absolute time would
//   never end; here it ends at once. For times later than the start both rules agree.)
// `end` never fires.
#include "gnc/mission.hpp"
#include "gnc/nav_state.hpp"

namespace gdnav::guidance {

// Times within this of a trigger's or the mission's end count as reached: guards against t accumulated in steps of
// 0.01 s, as the reference does.
inline constexpr double kTimeTolerance_s = 1e-10;

class TriggerState {
public:
    // Arms `trigger` for an operation starting at time t_s with estimate `est`.
    void start(const Trigger& trigger, double t_s, const NavState& est);
    // True when the trigger fires at this evaluation.
    bool fired(double t_s, const NavState& est);

    [[nodiscard]] double start_time_s() const { return t_start_s_; }

private:
    // Signed distance measured - target for crossing triggers (wrapped for bearing triggers).
    [[nodiscard]] double distance(const NavState& est) const;
    [[nodiscard]] bool is_bearing() const;

    Trigger trigger_{};
    double t_start_s_{0.0};
    bool active_{false};
    bool sign_{false};
};

}  // namespace gdnav::guidance
