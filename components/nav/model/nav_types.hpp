#pragma once
// Plain input and output structs of the navigation filters. They mirror the IDL topics of idl/gdnav.idl
// (ImuSample, MagSample, AirSample, AtmSample, GnssSample, AirDataEstimate, AttitudeEstimate, PositionEstimate)
// with Eigen vectors in place of arrays, so the component wrappers copy fields one to one. SI units; frames in
// names (n = NED, b = body). Fields marked [not in IDL] are needed by a filter but missing from the IDL topic.
#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace gdnav::nav {

using Vec3 = Eigen::Vector3d;
using Quat = Eigen::Quaterniond;

struct Stamp {
    std::uint64_t step{0};
    double t_s{0.0};
};

// ---------------------------------------------------------------- measurements
struct ImuSample {
    Vec3 f_b_mps2{Vec3::Zero()};  // measured specific force
    Vec3 w_b_rps{Vec3::Zero()};   // measured inertial angular rate
};
struct MagSample {
    Vec3 b_b_nT{Vec3::Zero()};
};
// Pre-flight fine alignment published with the IMU and magnetometer samples (ImuSample / MagSample align_*), used
// by `init.mode: alignment` (nav_init.hpp). Estimates at t0 with their 1-sigma.
struct Alignment {
    Quat q_nb{0.0, 0.0, 0.0, 0.0};  // body -> NED; zero = no alignment published
    double att_sigma_rad{0.0};
    Vec3 gyr_err_rps{Vec3::Zero()}, gyr_err_sigma_rps{Vec3::Zero()};
    Vec3 acc_err_mps2{Vec3::Zero()}, acc_err_sigma_mps2{Vec3::Zero()};
    Vec3 mag_err_nT{Vec3::Zero()}, mag_err_sigma_nT{Vec3::Zero()};
    Vec3 b_dev_n_nT{Vec3::Zero()}, b_dev_sigma_nT{Vec3::Zero()};
    [[nodiscard]] bool valid() const { return q_nb.coeffs().norm() > 0.5; }
};
// The attitude filter's state (attitude_model.hpp) with the quaternion as a rotation: what an initialisation, a
// hand-over and an estimate of the attitude all carry.
struct AttitudeState {
    Quat q_nb{Quat::Identity()};
    Vec3 w_nb_b_rps{Vec3::Zero()};
    Vec3 gyr_bias_rps{Vec3::Zero()};  // E_GYR
    Vec3 mag_bias_nT{Vec3::Zero()};   // E_MAG
    Vec3 b_dev_n_nT{Vec3::Zero()};    // B_DEV = B_model - B_true
};
// The state a joint GNSS/INS estimator hands to the attitude filter (in_flight_aligner.hpp, AttitudeFilter::hand_over):
// the estimates and the joint covariance of their errors, ordered [phi_n (attitude, NED side: R = exp([phi x]) R_hat),
// dE_gyr, dE_mag, dB_dev], so that the correlations a turn builds between heading and field errors are kept.
struct AttitudeHandover : AttitudeState {
    Eigen::Matrix<double, 12, 12> p_err{Eigen::Matrix<double, 12, 12>::Zero()};
};
struct AirSample {
    double tas_mps{0.0};
    double aoa_rad{0.0};
    double aos_rad{0.0};  // sideslip beta (vane output already with the sign of beta)
};
struct AtmSample {
    double p_Pa{0.0};  // static pressure
    double T_K{0.0};   // outside air temperature
};
struct GnssSample {
    bool fix_valid{false};
    double lon_rad{0.0};
    double lat_rad{0.0};
    double h_m{0.0};  // ellipsoidal height
    Vec3 v_n_mps{Vec3::Zero()};
};

// ---------------------------------------------------------------- estimates
struct AirDataEstimate {
    Stamp stamp;
    double tas_mps{0.0};
    double aoa_rad{0.0};
    double aos_rad{0.0};
    double dT_K{0.0};  // INSA temperature offset dT = T - (T0 + beta Hp)
    double Hp_m{0.0};  // pressure altitude (from the measured static pressure)
    double T_K{0.0};
    // [not in IDL] rate states of the 9-state air data filter, needed by the "wind integration" variant.
    double roc_mps{0.0};        // rate of climb dHp/dt
    double tas_dot_mps2{0.0};
    double aoa_dot_rps{0.0};
    double aos_dot_rps{0.0};
};

struct AttitudeEstimate : AttitudeState {
    Stamp stamp;
    Vec3 euler_rad{Vec3::Zero()};      // yaw, pitch, bank
    Vec3 att_sigma_rad{Vec3::Zero()};  // 1-sigma attitude uncertainty about N axes
};

struct PositionEstimate {
    Stamp stamp;
    double lon_rad{0.0};
    double lat_rad{0.0};
    double h_m{0.0};
    Vec3 v_n_mps{Vec3::Zero()};
    Vec3 wind_n_mps{Vec3::Zero()};
    double Hp_m{0.0};
    double dp_Pa{0.0};
    double dT_K{0.0};
    Vec3 acc_err_b_mps2{Vec3::Zero()};  // E_ACC
    bool gnss_denied{false};
    // [not in IDL, event for ComponentStatus MODE] true only on the step the filter switched to GNSS-denied.
    bool gnss_lost_event{false};
    // [not in IDL, event for ComponentStatus MODE] true only on the step the filter went back to GNSS-aided.
    bool gnss_reacquired_event{false};
    // [not in IDL] estimated specific force f_ib_b (position filter state), useful for diagnostics.
    Vec3 f_b_mps2{Vec3::Zero()};
};

}  // namespace gdnav::nav
