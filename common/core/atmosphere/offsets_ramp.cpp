#include "atmosphere/offsets_ramp.hpp"

#include <stdexcept>

namespace gdnav::core::atm {

double ramp_value(double t, double t0, double t1, double v0, double v1) {
    if (t <= t0) return v0;
    if (t >= t1) return v1;
    return v0 + (v1 - v0) * (t - t0) / (t1 - t0);
}

OffsetsRampParams draw_offsets_ramp(rnd::Stream& s, const OffsetsRampSpec& spec) {
    if (!spec.times.valid() || spec.sigma_dT0_K < 0.0 || spec.sigma_dp0_Pa < 0.0 || spec.sigma_dT_jump_K < 0.0 ||
        spec.sigma_dp_jump_Pa < 0.0)
        throw std::invalid_argument("draw_offsets_ramp: sigmas must be >= 0 (sigma_t > 0) and dt_mean >= 0");
    const rnd::RampTimesSpec& times = spec.times;
    OffsetsRampParams p;
    p.t_ini_dT_s = times.draw_start_s(s);
    p.t_ini_dp_s = times.draw_start_s(s);
    p.t_end_dT_s = times.draw_end_s(s, p.t_ini_dT_s, times.sigma_t_s);
    p.t_end_dp_s = times.draw_end_s(s, p.t_ini_dp_s, times.sigma_t_s);
    p.dT_ini_K = spec.sigma_dT0_K * s.normal();
    p.dp_ini_Pa = spec.sigma_dp0_Pa * s.normal();
    p.dT_end_K = p.dT_ini_K + spec.sigma_dT_jump_K * s.normal();
    p.dp_end_Pa = p.dp_ini_Pa + spec.sigma_dp_jump_Pa * s.normal();
    return p;
}

OffsetsRampParams draw_offsets_scenario(rnd::Stream& s, bool jumps) {
    OffsetsRampSpec spec;
    if (!jumps) spec.sigma_dT_jump_K = spec.sigma_dp_jump_Pa = 0.0;
    return draw_offsets_ramp(s, spec);
}

Offsets OffsetsRamp::at(double t_s) const {
    return {ramp_value(t_s, p_.t_ini_dT_s, p_.t_end_dT_s, p_.dT_ini_K, p_.dT_end_K),
            ramp_value(t_s, p_.t_ini_dp_s, p_.t_end_dp_s, p_.dp_ini_Pa, p_.dp_end_Pa)};
}

}  // namespace gdnav::core::atm
