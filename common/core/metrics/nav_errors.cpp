#include "metrics/nav_errors.hpp"

#include <cmath>

namespace gdnav::core::metrics {

HorizontalError horizontal_error(double lat_est_rad, double lon_est_rad, const NavState& truth,
                                 const earth::Radii& radii0) {
    HorizontalError e;
    e.north_m = (lat_est_rad - truth.lat_rad) * (radii0.m_m + truth.h_m);
    e.east_m = math::wrap_pi(lon_est_rad - truth.lon_rad) * (radii0.n_m + truth.h_m) * std::cos(truth.lat_rad);
    e.hor_m = std::hypot(e.north_m, e.east_m);
    const double chi = std::atan2(truth.v_n_mps.y(), truth.v_n_mps.x());
    const double c = std::cos(chi);
    const double s = std::sin(chi);
    e.cross_m = e.east_m * c - e.north_m * s;
    e.along_m = e.north_m * c + e.east_m * s;
    return e;
}

NavErrors nav_errors(const NavState& est, const NavState& truth, const earth::Radii& radii0) {
    NavErrors e;
    const math::Euler ee = math::euler_from_quat(est.q_nb);
    const math::Euler et = math::euler_from_quat(truth.q_nb);
    e.yaw_rad = math::wrap_pi(ee.yaw_rad - et.yaw_rad);
    e.pitch_rad = ee.pitch_rad - et.pitch_rad;
    e.bank_rad = math::wrap_pi(ee.bank_rad - et.bank_rad);
    e.rot_rad = math::angle_between(truth.q_nb, est.q_nb);
    e.tas_mps = est.tas_mps - truth.tas_mps;
    e.aoa_rad = est.aoa_rad - truth.aoa_rad;
    e.aos_rad = est.aos_rad - truth.aos_rad;
    e.dT_K = est.dT_K - truth.dT_K;
    e.h_m = est.h_m - truth.h_m;
    e.v_n_mps = est.v_n_mps - truth.v_n_mps;
    static_cast<HorizontalError&>(e) = horizontal_error(est.lat_rad, est.lon_rad, truth, radii0);
    return e;
}

}  // namespace gdnav::core::metrics
