#include "flight_physics/model/wind_ramp.hpp"

#include <cmath>
#include <stdexcept>

namespace gdnav::physics {

WindRampParams draw_wind_ramp(rnd::Stream& s, const WindRampSpec& spec) {
    if (!spec.times.valid() || spec.sigma_speed0_mps < 0.0 || spec.sigma_speed_jump_mps < 0.0 ||
        spec.sigma_bearing_jump_rad < 0.0)
        throw std::invalid_argument("draw_wind_ramp: sigmas must be >= 0 (sigma_t > 0) and dt_mean >= 0");
    WindRampParams p;
    p.t_ini_s = spec.times.draw_start_s(s);
    p.t_end_s = spec.times.draw_end_s(s, p.t_ini_s, 0.5 * spec.times.sigma_t_s);
    p.speed_ini_mps = std::abs(spec.sigma_speed0_mps * s.normal());
    p.bearing_ini_rad = math::deg2rad(static_cast<double>(s.uniform_int(-179, 180)));
    p.speed_end_mps = p.speed_ini_mps + spec.sigma_speed_jump_mps * s.normal();
    double chi_end = p.bearing_ini_rad + spec.sigma_bearing_jump_rad * s.normal();
    if (p.speed_end_mps < 0.0) {
        p.speed_end_mps = -p.speed_end_mps;
        chi_end += math::kPi;
    }
    p.bearing_end_rad = math::wrap_pi(chi_end);
    return p;
}

WindRampParams draw_wind_scenario(rnd::Stream& s, bool jumps) {
    WindRampSpec spec;
    if (!jumps) spec.sigma_speed_jump_mps = spec.sigma_bearing_jump_rad = 0.0;
    return draw_wind_ramp(s, spec);
}

WindRamp::WindRamp(const WindRampParams& p)
    : p_(p),
      w_ini_(p.speed_ini_mps * std::cos(p.bearing_ini_rad), p.speed_ini_mps * std::sin(p.bearing_ini_rad), 0.0),
      w_end_(p.speed_end_mps * std::cos(p.bearing_end_rad), p.speed_end_mps * std::sin(p.bearing_end_rad), 0.0) {}

math::Vec3 WindRamp::wind_n_mps(double t) const {
    if (t <= p_.t_ini_s) return w_ini_;
    if (t >= p_.t_end_s) return w_end_;
    return w_ini_ + (w_end_ - w_ini_) * ((t - p_.t_ini_s) / (p_.t_end_s - p_.t_ini_s));
}

}  // namespace gdnav::physics
