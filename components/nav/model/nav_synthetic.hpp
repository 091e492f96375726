#pragma once
// Synthetic flight and sensor data for the filter tests and the benchmark (NOT a physics model: the real
// simulation is flight_physics + sensors). Kinematically exact for the filters' equations:
//   attitude: yaw = yaw0 + yaw_rate t, pitch and bank constant  =>  w_nb_b = yaw_rate (-sin th, sin ph cos th, cos ph cos th)
//   airspeed vector constant in body (v_tas_b = vtas_body(V, aoa, aos)), wind constant in NED, no turbulence:
//     v_n = wind_n + R v_tas_b,   v_n_dot = R (w_nb x v_tas_b)
//   specific force (paper eq. force8_N):  f_b = R^T (v_n_dot + w_en x v_n - g_model + a_cor)
//   gyro: w_ib = w_nb + R^T (w_ie + w_en) + E_gyr + noise;  mag: B_b = R^T (B_model - B_dev) + E_mag + noise
//   atmosphere (INSA with constant dT, dp): Hp from H = R_E h / (R_E + h); p = p(Hp); T = T0 + dT + beta Hp
//   GNSS every `gnss_period_steps` steps: position (m-level noise) and velocity with white noise.
// Position is integrated with forward Euler at the step rate; the truth is whatever the generator integrates.
#include <cstdint>
#include <limits>

#include "nav_init.hpp"
#include "nav_types.hpp"
#include "random/stream.hpp"

namespace gdnav::nav::synth {

struct Scenario {
    double dt_s{0.01};
    double t0_s{0.0};
    double lon0_rad{-1.5707963267948966};  // 270 deg east
    double lat0_rad{0.7853981633974483};   // 45 deg
    double h0_m{3000.0};
    double yaw0_rad{0.5};
    double yaw_rate_rps{0.0};
    // If finite: from this time on the bank rolls to its opposite over reverse_roll_s (coordinated, the turn the
    // other way). Kinematically exact only with aoa_rad = aos_rad = 0 (v_tas_b on the roll axis, so the roll does not
    // move the velocity); the yaw is then integrated step by step.
    double reverse_turn_at_s{std::numeric_limits<double>::infinity()};
    double reverse_roll_s{3.0};
    double pitch_rad{0.03};
    double bank_rad{0.0};
    double tas_mps{30.0};
    double aoa_rad{0.03};
    double aos_rad{0.0};
    Vec3 wind_n_mps{3.0, -4.0, 0.0};
    double dT_K{5.0};
    double dp_Pa{300.0};
    int gnss_period_steps{100};
    // sensor errors (constant) and white-noise 1-sigmas per sample
    Vec3 gyr_err_b_rps{Vec3::Zero()};
    Vec3 acc_err_b_mps2{Vec3::Zero()};
    Vec3 mag_err_b_nT{Vec3::Zero()};
    Vec3 b_dev_n_nT{Vec3::Zero()};  // B_model - B_true
    double gyr_sigma_rps{7.505e-4};
    double acc_sigma_mps2{4.83e-3};
    double mag_sigma_nT{50.0};
    double tas_sigma_mps{0.333};
    double angle_sigma_rad{5.81e-3};
    double p_sigma_Pa{100.0};
    double T_sigma_K{0.05};
    double gnss_hor_sigma_m{2.12};
    double gnss_ver_sigma_m{4.25};
    double gnss_v_sigma_mps{0.0741};
};

struct Truth {
    double t_s{0.0};
    Quat q_nb{Quat::Identity()};
    Vec3 w_nb_b_rps{Vec3::Zero()};
    double lon_rad{0.0}, lat_rad{0.0}, h_m{0.0};
    Vec3 v_n_mps{Vec3::Zero()};
    double Hp_m{0.0};
};

struct Sample {
    Truth truth;
    ImuSample imu;
    MagSample mag;
    AirSample air;
    AtmSample atm;
    GnssSample gnss;
};

class Generator {
public:
    Generator(const Scenario& sc, rnd::Stream stream);
    // Sample of step k (call with k = 0, 1, 2, ... in order).
    Sample next();
    [[nodiscard]] const Scenario& scenario() const { return sc_; }
    // The pre-flight alignment the sensors would publish for this scenario, with the reference's error model
    // (sensors::AlignmentErrors defaults, drawn from `stream`); perfect when `exact`.
    [[nodiscard]] Alignment alignment(rnd::Stream stream, bool exact = false) const;

private:
    Scenario sc_;
    rnd::Stream stream_;
    std::uint64_t k_{0};
    double lon_{0.0}, lat_{0.0}, h_{0.0};
    double yaw_{0.0};  // integrated yaw, used only with a turn reversal
};

// Pressure altitude whose INSA geopotential altitude (with dT, dp) equals H (Newton on H_from_Hp).
double Hp_from_H(double h_geopot_m, double dt_k, double dp_pa);

}  // namespace gdnav::nav::synth
