#include "trigger.hpp"

#include <cmath>

namespace gdnav::guidance {

namespace {
constexpr double kBearingWindow_rad = math::kPi / 2.0;
}  // namespace


bool TriggerState::is_bearing() const {
    return trigger_.kind == TriggerKind::bearing || trigger_.kind == TriggerKind::heading;
}

double TriggerState::distance(const NavState& est) const {
    switch (trigger_.kind) {
        case TriggerKind::bearing: return math::wrap_pi(est.ground_bearing_rad - trigger_.value);
        case TriggerKind::heading: return math::wrap_pi(est.heading_rad - trigger_.value);
        case TriggerKind::pressure_altitude: return est.pressure_altitude_m - trigger_.value;
        case TriggerKind::altitude: return est.altitude_m - trigger_.value;
        case TriggerKind::path_angle: return est.path_angle_rad - trigger_.value;
        case TriggerKind::airspeed: return est.airspeed_mps - trigger_.value;
        case TriggerKind::time:
        case TriggerKind::elapsed:
        case TriggerKind::end: break;
    }
    return 0.0;
}

void TriggerState::start(const Trigger& trigger, double t_s, const NavState& est) {
    trigger_ = trigger;
    t_start_s_ = t_s;
    const double d = distance(est);
    active_ = !is_bearing() || std::fabs(d) <= kBearingWindow_rad;
    sign_ = d >= 0.0;
}

bool TriggerState::fired(double t_s, const NavState& est) {
    switch (trigger_.kind) {
        case TriggerKind::time: return t_s + kTimeTolerance_s >= trigger_.value;
        case TriggerKind::elapsed: return t_s + kTimeTolerance_s - t_start_s_ >= trigger_.value;
        case TriggerKind::end: return false;
        default: break;
    }
    const double d = distance(est);
    if (is_bearing()) {
        if (std::fabs(d) > kBearingWindow_rad) {
            active_ = false;
            return false;
        }
        if (!active_) {  // re-arm on the first evaluation back inside the window
            active_ = true;
            sign_ = d >= 0.0;
            return false;
        }
    }
    return (d >= 0.0) != sign_;
}

}  // namespace gdnav::guidance
