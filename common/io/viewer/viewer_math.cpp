#include "io/viewer/viewer_math.hpp"

#include <cmath>

namespace gdnav::io::viewer {

math::Quat quat_enu_flu(const math::Quat& q_nb) {
    const double h = std::sqrt(0.5);
    const math::Quat q_enu_ned(0.0, h, h, 0.0);    // w, x, y, z: 180 deg about (1, 1, 0)/sqrt 2
    const math::Quat q_frd_flu(0.0, 1.0, 0.0, 0.0);  // 180 deg about x
    math::Quat q = q_enu_ned * q_nb * q_frd_flu;
    if (q.w() < 0.0) q.coeffs() = -q.coeffs();  // one sign for the same rotation: w >= 0
    return q;
}

math::Vec3 enu_offset_m(const earth::Geodetic& origin, const earth::Geodetic& p) {
    const math::Vec3 d_e = earth::ecef_from_geodetic(p) - earth::ecef_from_geodetic(origin);
    const math::Vec3 d_n = earth::dcm_ecef_from_ned(origin.lon_rad, origin.lat_rad).transpose() * d_e;
    return {d_n.y(), d_n.x(), -d_n.z()};
}

TimeParts time_parts(std::uint64_t ns) {
    return {static_cast<std::uint32_t>(ns / 1'000'000'000ULL), static_cast<std::uint32_t>(ns % 1'000'000'000ULL)};
}

NavErrorValues nav_error_values(const metrics::NavState& est, const metrics::NavState& truth,
                                const earth::Radii& radii0) {
    const metrics::NavErrors e = metrics::nav_errors(est, truth, radii0);
    NavErrorValues v;
    v.att_err_deg = math::rad2deg(e.rot_rad);
    v.yaw_err_deg = math::rad2deg(e.yaw_rad);
    v.pitch_err_deg = math::rad2deg(e.pitch_rad);
    v.bank_err_deg = math::rad2deg(e.bank_rad);
    v.hor_err_m = e.hor_m;
    v.cross_err_m = e.cross_m;
    v.along_err_m = e.along_m;
    v.alt_err_m = e.h_m;
    v.vn_err_mps = e.v_n_mps.x();
    v.ve_err_mps = e.v_n_mps.y();
    v.gs_err_mps = std::hypot(est.v_n_mps.x(), est.v_n_mps.y()) - std::hypot(truth.v_n_mps.x(), truth.v_n_mps.y());
    v.tas_err_mps = e.tas_mps;
    return v;
}

}  // namespace gdnav::io::viewer
