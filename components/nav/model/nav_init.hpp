#pragma once
// Initial estimates of the attitude and position filters (models-nav.md §6).
//
// Two modes, chosen by `init.mode` in each filter's tuning section:
//  * measurements (default, truth-free): everything comes from the first measurements and the first GNSS fix.
//      attitude: leveling from the specific force corrected for the turn term, g_b = -(f~ - w~ x v_tas_b), and
//                magnetic heading from the levelled magnetometer and the model declination:
//                  pitch = atan2(-g_x, sqrt(g_y^2 + g_z^2)), bank = atan2(g_y, g_z),
//                  B_h = R_y(pitch) R_x(bank) B~,  yaw = atan2(B_model_E, B_model_N) - atan2(B_h,y, B_h,x);
//                E_gyr, E_mag, B_dev, E_acc start at 0 with the 1-sigma of the sensor-grade bias offsets /
//                WMM error budget given in the tuning file.
//  * reference (models-nav.md §6, reproduces the paper's runs): estimates = truth at t0 plus small random errors,
//      drawn from the filter's Stream:  q0 = dq (x) q_true (NED-side error, rotation vector gamma * a,
//      gamma ~ N(0, 0.1 deg), a = (cos p1 cos p2, sin p2, sin p1) with p1 integer degrees U[-179, 180], p2 = (integer
//      U[-179, 180])/2 degrees); E_gyr/E_acc/E_mag = truth (x) (1 + 0.01 nu); B_dev = truth (x) (1 + 0.1 nu);
//      1-sigma = 0.01 |truth| (0.1 for B_dev); attitude P0 = 1e-8 per quaternion component (reference value).
//      Deviation (reference bug, models-nav.md §10.10): `a` is not unit length in the reference, inflating the
//      angle by up to sqrt(2); we normalise it (switch `normalise_error_axis`).
//    This mode needs StartTruth (true attitude and full sensor errors at t0), which no IDL topic carries today.
#include "nav_types.hpp"
#include "random/stream.hpp"

namespace gdnav::nav {

enum class InitMode { kMeasurements, kReference };

// Truth at the first step, only for `init.mode: reference`.
struct StartTruth {
    Quat q_nb{Quat::Identity()};
    Vec3 gyr_err_b_rps{Vec3::Zero()};   // full gyro error E_gyr (no noise)
    Vec3 acc_err_b_mps2{Vec3::Zero()};  // full accelerometer error E_acc
    Vec3 mag_err_b_nT{Vec3::Zero()};    // full magnetometer error E_mag
    Vec3 b_dev_n_nT{Vec3::Zero()};      // B_model - B_true at the initial position
};

// Reference-mode error model (models-nav.md §6, baseline values).
struct ReferenceInitErrors {
    double att_sigma_rad{0.1 * 3.14159265358979323846 / 180.0};
    double q_p0{1e-8};  // attitude P0 per quaternion component
    double gyr_rel{0.01};
    double acc_rel{0.01};
    double mag_rel{0.01};
    double b_dev_rel{0.10};
    bool normalise_error_axis{true};
};

// Truth-free mode 1-sigmas.
struct MeasurementInitSigmas {
    double att_rad{0.05};
    Vec3 gyr_bias_rps{Vec3::Constant(3.49e-3)};
    Vec3 acc_bias_mps2{Vec3::Constant(0.157)};
    Vec3 mag_bias_nT{Vec3::Constant(530.0)};
    Vec3 b_dev_nT{138.0, 89.0, 165.0};
};

// Coarse attitude from one specific-force sample (gravity direction g_b, already corrected for the turn term)
// and one magnetometer sample (bias-corrected), with the model field b_model_n giving the declination.
Quat coarse_attitude(const Vec3& f_corrected_b, const Vec3& b_b_nT, const Vec3& b_model_n_nT);

// NED-side attitude error of the reference (see header comment), drawn from `stream`.
Quat draw_attitude_error(double sigma_rad, bool normalise_axis, rnd::Stream& stream);

// truth (x) (1 + rel nu), nu ~ N(0, I3) (component-wise).
Vec3 perturb_relative(const Vec3& truth, double rel, rnd::Stream& stream);

}  // namespace gdnav::nav
