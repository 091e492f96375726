#pragma once
// Navigation system errors (NSE) of one step: estimate minus truth, with the conventions of the paper and of the
// reference's output code (docs/montecarlo.md, "nav_recorder: errors, online metrics and files").
//
//   attitude   Euler 3-2-1 errors of the estimated and true q_nb: yaw and bank errors wrapped to (-pi, pi];
//              rotation angle |Delta r| = |log(q_true^-1 (x) q_est)| in [0, pi]  (the norm of the rotation vector)
//   air data   TAS, AOA, AOS and temperature-offset dT errors (AirDataEstimate - Truth)
//   vertical   geometric altitude error h_est - h
//   velocity   ground velocity errors v_est^n - v^n (N, E, D)
//   horizontal e_N = (lat_est - lat) (M_0 + h),  e_E = wrap(lon_est - lon) (N_0 + h) cos(lat)
//              with the radii of curvature M_0, N_0 at the INITIAL latitude and the current TRUE lat, h;
//              e_hor = sqrt(e_N^2 + e_E^2);
//              relative to the true ground-track bearing chi = atan2(v_E, v_N):
//                e_cross = e_E cos chi - e_N sin chi   (> 0: the estimate lies to the right of the true track)
//                e_along = e_N cos chi + e_E sin chi   (> 0: the estimate lies ahead)
//              i.e. e_hor sin(a) and e_hor cos(a) with a = atan2(e_E, e_N) - chi, as the reference. (The reference's
//              aggregation code swaps the two in its tables; here each is what its name says.)
// Units: SI (rad, m, m/s, K). Frames: N = local NED.
#include "earth/wgs84.hpp"
#include "math/rotation.hpp"

namespace gdnav::core::metrics {

// The navigation state compared (filled from Truth or from the three estimate topics).
struct NavState {
    double lat_rad{0.0};
    double lon_rad{0.0};
    double h_m{0.0};
    math::Vec3 v_n_mps{math::Vec3::Zero()};
    math::Quat q_nb{math::Quat::Identity()};
    double tas_mps{0.0};
    double aoa_rad{0.0};
    double aos_rad{0.0};
    double dT_K{0.0};
};

struct HorizontalError {
    double north_m{0.0};
    double east_m{0.0};
    double hor_m{0.0};
    double cross_m{0.0};
    double along_m{0.0};
};

// The step's errors: the horizontal ones (the base) and all the others.
struct NavErrors : HorizontalError {
    double yaw_rad{0.0};
    double pitch_rad{0.0};
    double bank_rad{0.0};
    double rot_rad{0.0};
    double tas_mps{0.0};
    double aoa_rad{0.0};
    double aos_rad{0.0};
    double dT_K{0.0};
    double h_m{0.0};
    math::Vec3 v_n_mps{math::Vec3::Zero()};
};

// Horizontal error decomposition (see above). `radii0` are the radii at the initial latitude.
HorizontalError horizontal_error(double lat_est_rad, double lon_est_rad, const NavState& truth,
                                 const earth::Radii& radii0);

// All errors of one step.
NavErrors nav_errors(const NavState& est, const NavState& truth, const earth::Radii& radii0);

}  // namespace gdnav::core::metrics
namespace gdnav { namespace metrics = core::metrics; }  // the short name (docs/architecture.md, "Namespaces")
