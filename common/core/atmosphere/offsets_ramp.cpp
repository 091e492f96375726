#include "atmosphere/offsets_ramp.hpp"

#include <stdexcept>

namespace gdnav::atm {

double ramp_value(double t, double t0, double t1, double v0, double v1) {
    if (t <= t0) return v0;
    if (t >= t1) return v1;
    return v0 + (v1 - v0) * (t - t0) / (t1 - t0);
}

OffsetsRampParams draw_offsets_ramp(rnd::Stream& s, const OffsetsRampSpec& spec) {
    // The redraw loops below terminate with probability one only if the acceptance regions have positive mass.
    if (!(spec.sigma_t_s > 0.0) || !(spec.dt_mean_s >= 0.0) || spec.sigma_dT0_K < 0.0 || spec.sigma_dp0_Pa < 0.0 ||
        spec.sigma_dT_jump_K < 0.0 || spec.sigma_dp_jump_Pa < 0.0)
        throw std::invalid_argument("draw_offsets_ramp: sigmas must be >= 0 (sigma_t > 0) and dt_mean >= 0");
    auto draw_ini = [&] {
        double t = 0.0;
        do {
            t = spec.t_ini_mean_s + spec.sigma_t_s * s.normal();
        } while (t < spec.t_min_s);
        return t;
    };
    auto draw_end = [&](double t_ini) {
        double t = 0.0;
        do {
            t = t_ini + spec.dt_mean_s + spec.sigma_t_s * s.normal();
        } while (t < t_ini + spec.sigma_t_s);
        return t;
    };
    OffsetsRampParams p;
    p.t_ini_dT_s = draw_ini();
    p.t_ini_dp_s = draw_ini();
    p.t_end_dT_s = draw_end(p.t_ini_dT_s);
    p.t_end_dp_s = draw_end(p.t_ini_dp_s);
    p.dT_ini_K = spec.sigma_dT0_K * s.normal();
    p.dp_ini_Pa = spec.sigma_dp0_Pa * s.normal();
    p.dT_end_K = p.dT_ini_K + spec.sigma_dT_jump_K * s.normal();
    p.dp_end_Pa = p.dp_ini_Pa + spec.sigma_dp_jump_Pa * s.normal();
    return p;
}

Offsets OffsetsRamp::at(double t_s) const {
    return {ramp_value(t_s, p_.t_ini_dT_s, p_.t_end_dT_s, p_.dT_ini_K, p_.dT_end_K),
            ramp_value(t_s, p_.t_ini_dp_s, p_.t_end_dp_s, p_.dp_ini_Pa, p_.dp_end_Pa)};
}

}  // namespace gdnav::atm
