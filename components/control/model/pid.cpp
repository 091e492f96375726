#include "pid.hpp"

#include <algorithm>

namespace gdnav::control {

DiscretePid::DiscretePid(const PidGains& gains, double filter_time_s, double dt_s)
    : gains_(gains), filter_time_s_(filter_time_s), dt_s_(dt_s) {}

void DiscretePid::reset() {
    integral_ = 0.0;
    filtered_ = 0.0;
    derivative_ = 0.0;
}

double DiscretePid::step_unsaturated(double error) {
    integral_ += error;
    const double filtered = (filter_time_s_ * filtered_ + dt_s_ * error) / (filter_time_s_ + dt_s_);
    derivative_ = filtered - filtered_;
    filtered_ = filtered;
    return gains_.u_eq + gains_.kp * error + gains_.ki * integral_ + gains_.kd * derivative_;
}

double DiscretePid::saturate(double u) const { return std::clamp(u, gains_.u_min, gains_.u_max); }

}  // namespace gdnav::control
