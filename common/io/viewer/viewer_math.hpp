#pragma once
// The derived quantities of the viewer channels (viewer_channels.hpp), plain C++ without DDS:
//
//   geodetic degrees      latitude/longitude in degrees (foxglove.LocationFix) = math::rad2deg of the radians;
//   attitude in ENU/FLU   the 3D panels of Foxglove and Lichtblick draw z up (ROS REP 103), so the viewer's world
//                         frame is the local East-North-Up plane at the initial true position and the body axes are
//                         x forward, y left, z up:  q_enu_flu = q_enu_ned (x) q_nb (x) q_frd_flu, with
//                         q_enu_ned = 180 deg about (1, 1, 0)/sqrt 2 (x_enu = y_ned, y_enu = x_ned, z_enu = -z_ned)
//                         and q_frd_flu = 180 deg about x (gdnav's body axes are x forward, y right, z down);
//   position in ENU       the exact local East-North-Up offset of a point from the origin (WGS84 ECEF difference
//                         rotated into the origin's tangent plane, common/core/earth);
//   navigation errors     metrics::nav_errors (common/core/metrics, the same values as run.h5 /error) in the viewer's
//                         units (deg, m, m/s) plus the ground-speed error |v_est NE| - |v NE|.
#include <cstdint>

#include "earth/wgs84.hpp"
#include "math/rotation.hpp"
#include "metrics/nav_errors.hpp"

namespace gdnav::io::viewer {

// Attitude body (x forward, y left, z up) -> ENU from gdnav's q_nb (body x forward, y right, z down -> NED).
math::Quat quat_enu_flu(const math::Quat& q_nb);

// East, north, up offsets [m] of `p` from `origin` in the origin's local tangent plane.
math::Vec3 enu_offset_m(const earth::Geodetic& origin, const earth::Geodetic& p);

// foxglove.Time of a log time in nanoseconds (sec = floor(ns / 1e9), nsec = the rest).
struct TimeParts {
    std::uint32_t sec{0};
    std::uint32_t nsec{0};
};
TimeParts time_parts(std::uint64_t ns);

// The errors of one step as the viewer shows them.
struct NavErrorValues {
    double att_err_deg{0.0};
    double yaw_err_deg{0.0};
    double pitch_err_deg{0.0};
    double bank_err_deg{0.0};
    double hor_err_m{0.0};
    double cross_err_m{0.0};
    double along_err_m{0.0};
    double alt_err_m{0.0};
    double vn_err_mps{0.0};
    double ve_err_mps{0.0};
    double gs_err_mps{0.0};
    double tas_err_mps{0.0};
};
// `radii0`: the radii of curvature at the initial true latitude (as nav_recorder's metrics).
NavErrorValues nav_error_values(const metrics::NavState& est, const metrics::NavState& truth,
                                const earth::Radii& radii0);

}  // namespace gdnav::io::viewer
