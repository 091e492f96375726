#include "sensors/model/platform.hpp"

#include <algorithm>

namespace gdnav::sensors {

PlatformMounting draw_platform(const PlatformParams& p, rnd::Stream& stream) {
    PlatformMounting m;
    const math::Vec3 a = stream.normal3();
    const math::Vec3 e = stream.normal3();
    const math::Vec3 x = stream.normal3();
    m.euler_bp_true = {p.mounting_sigma_rad[0] * a[0], p.mounting_sigma_rad[1] * a[1], p.mounting_sigma_rad[2] * a[2]};
    const double se = p.mounting_estimate_error_rad;
    m.euler_bp_est = {m.euler_bp_true.yaw_rad + se * e[0], m.euler_bp_true.pitch_rad + se * e[1],
                      m.euler_bp_true.bank_rad + se * e[2]};
    m.r_bp_true = math::dcm_from_euler(m.euler_bp_true);
    m.r_bp_est = math::dcm_from_euler(m.euler_bp_est);
    m.t_rp_true_m = p.imu_position_m;
    m.t_rp_est_m = p.imu_position_m + p.imu_position_error_m * x;
    return m;
}

math::Vec3 cg_position_m(const PlatformParams& p, double mass_kg) {
    const double span = p.mass_full_kg - p.mass_empty_kg;
    const double r = span > 0.0 ? std::clamp((p.mass_full_kg - mass_kg) / span, 0.0, 1.0) : 0.0;
    return p.cg_full_m + r * (p.cg_empty_m - p.cg_full_m);
}

}  // namespace gdnav::sensors
