#pragma once
// In-flight fine alignment (docs/navigation.md, "In-flight fine alignment"): one GNSS-aided strapdown INS with the
// magnetometer calibration in its state, run from the truth-free start until its own covariance says that the
// attitude, the sensor errors and the field error are known as well as a pre-flight fine alignment would give them;
// then the navigation filters are started again from it (`Alignment`, as from the sensors' published alignment).
// With the hand-over at the GNSS loss (variant keep_gnss_calibration; docs/navigation.md, "Keeping the GNSS
// calibration") the same estimator runs through the whole GNSS-aided phase instead, from the truth-free start or from
// the sensors' published alignment, and hands its attitude, sensor and field errors and their joint covariance to the
// attitude filter at the loss (`handover()`); its alignment criteria then only raise the aligned flag.
//
// Why a joint filter: the paper's filters are a cascade (the attitude filter takes E_acc and p_n from the position
// filter, the position filter takes the attitude as exact), so the heading and tilt information that the GNSS sees
// in a turn cannot reach the attitude; here one covariance holds them all.
//
// Error state (39), true = estimate + error, the attitude error phi on the NED side (R = exp([phi x]) R_hat):
//   phi(0..2), dv_n(3..5), dp_NED [m](6..8), dE_gyr(9..11), dE_acc(12..14), dE_mag(15..17), dB_dev(18..20),
//   and, used only when the estimator runs through the denied phase (HandOver::kNever): dw_n (21..23, the wind) and
//   dM (24..32, row by row: the magnetometer's scale factor, cross coupling and soft iron, B~ = (I + M) b + E_mag,
//   which turns with the aircraft and so is not a constant E_mag once it flies other headings than it was learnt on),
//   dt_n (33..35, the turbulence, NED, first-order Gauss-Markov) and db_air (36..38, the air data's offsets: TAS [m/s],
//   AOA, AOS [rad], constant)
// Mechanisation (NED, ellipsoidal Earth of nav_earth): w_nb = w~ - E_gyr - R^T (w_ie + w_en);
//   v_dot = R (f~ - E_acc) + g_n - (2 w_ie + w_en) x v;  (lon, lat, h)_dot from v.
// Error dynamics: phi_dot = -R dE_gyr;  dv_dot = -[f_n x] phi - R dE_acc;  dp_dot = dv;  errors of E_*, B_dev: walks.
// Magnetometer (every mag_period_steps): B~ = (I + M) R^T (B_model - B_dev) + E_mag, b = R^T (B_model - B_dev),
//   H = [(I + M) R^T [(B_model - B_dev) x], 0, 0, 0, 0, I, -(I + M) R^T, 0, I (x) b^T].
// GNSS fix: position (NED metres from the estimate) and velocity, H = [0 0 I ...; 0 I 0 ...], no lever arm.
// Air data (HandOver::kNever only, every air_period_steps, before and after the loss): the ground velocity is the air
// velocity turned to NED plus the wind and the turbulence, v_n = R v_air_b(TAS - b_tas, AOA - b_aoa, AOS - b_aos) + w_n
// + t_n; residual R_hat v_air_b + w_hat + t_hat - v_hat, H = [[(R_hat v_air_b) x], I, 0, 0, 0, 0, 0, -I, 0, -I, R_hat J]
// (J = d v_air_b / d(TAS, AOA, AOS)); the wind walks (wind_walk_mps_s_rts: the wind's slow changes), the turbulence
// decays with turb_tau_s to its stationary turb_sigma_mps (a correlated error the air data cannot average away, so
// not a white measurement noise). After the loss it is the velocity reference: it holds the tilt through gravity (the velocity's
// slope is phi x g + R dE_acc + the wind's acceleration) and with the magnetometer (mag_noise_nT) keeps the
// heading, gyro bias and field calibration the GNSS phase found (docs/navigation.md, "Keeping the GNSS
// calibration").
// Aligned (latched) at a GNSS fix once tilt and heading sigmas have been below their limits for hold_s, and not
// before not_before_s (the calibrated scenarios hand over at the paper's t0, where its filters start from the
// pre-flight alignment). Handed over at that moment, or at the GNSS loss (HandOver::kAtGnssLoss).
#include <cstdint>
#include <limits>

#include "config/config.hpp"
#include "filters/ekf.hpp"
#include "math/rotation.hpp"
#include "nav_types.hpp"

namespace gdnav::nav {

struct InFlightAlignerSettings {
    // Start (truth-free: one-sample levelling and magnetic heading, sensor-grade errors).
    double tilt_sigma_rad{math::deg2rad(1.5)};
    double heading_sigma_rad{math::deg2rad(10.0)};
    double gyr_bias_sigma_rps{math::deg2rad(0.2)};
    double acc_bias_sigma_mps2{0.157};
    double mag_bias_sigma_nT{530.0};
    double b_dev_sigma_nT{200.0};
    // Noise (white densities and walks) and measurements: the baseline sensors' figures (config/sensors), the walks
    // doubled, the GNSS position widened to cover the ionospheric walk.
    double gyr_noise_rps_rts{math::deg2rad(4.3e-3)};
    double acc_noise_mps2_rts{5.0e-4};
    double gyr_bias_walk_rps_s_rts{math::deg2rad(2.84e-4)};
    double acc_bias_walk_mps2_s_rts{1.4e-4};
    double mag_walk_nT_rts{0.1};
    double mag_noise_nT{50.0};
    int mag_period_steps{10};
    double gnss_hor_sigma_m{8.0};
    double gnss_ver_sigma_m{12.0};
    double gnss_vel_sigma_mps{0.075};
    // Air data and wind (HandOver::kNever only).
    double wind_sigma_mps{3.0};             // at the start, per axis
    double wind_walk_mps_s_rts{0.05};
    double air_vel_sigma_mps{0.5};          // per axis, per air-data update, while GNSS is there
    double air_vel_sigma_denied_mps{3.0};   // the same after the loss (see in_flight_aligner.cpp, update_air)
    int air_period_steps{10};
    double turb_sigma_mps{0.3};  // per NED axis, stationary (the Dryden gusts of the scenarios' turbulence factor)
    double turb_tau_s{10.0};     // its correlation time
    double tas_offset_sigma_mps{0.333};            // the air data's offsets at the start (the baseline
    double aoa_offset_sigma_rad{math::deg2rad(0.333)};  // sensors' bias offsets, config/sensors)
    double aos_offset_sigma_rad{math::deg2rad(0.333)};
    double mag_scale_sigma{7.5e-4};   // the diagonal of M at the start (the baseline magnetometer's scale factor)
    double mag_cross_sigma{9.16e-4};  // its other terms (the baseline's cross coupling)
    // Hand-over.
    double tilt_sigma_max_rad{math::deg2rad(0.05)};
    double heading_sigma_max_rad{math::deg2rad(0.05)};
    double hold_s{10.0};
    double not_before_s{-std::numeric_limits<double>::infinity()};  // no hand-over before this time
};

// When the estimator hands over to the paper's filters: once aligned (the in-flight alignment), at the GNSS loss
// (it runs through the whole GNSS-aided phase), or never (it runs through the denied phase too, on air data and the
// magnetometer; `hand_over()` then only marks the loss).
enum class HandOver { kAtAlignment, kAtGnssLoss, kNever };

// Reads an `in_flight_alignment` section (every key optional; keys and ranges in in_flight_aligner.cpp); a key not
// given keeps its value in `base`.
InFlightAlignerSettings parse_in_flight_alignment(const config::Config& c,
                                                  const InFlightAlignerSettings& base = InFlightAlignerSettings{});

class InFlightAligner {
public:
    static constexpr int kN = 39;
    InFlightAligner() = default;
    InFlightAligner(const InFlightAlignerSettings& s, double dt_s, HandOver mode = HandOver::kAtAlignment);

    // Truth-free start on the first step with a valid fix: coarse attitude from the specific force less w x v_tas
    // and the magnetometer, position and velocity from the fix, sensor errors zero.
    void start(double t_s, const ImuSample& imu, const MagSample& mag, const GnssSample& fix, const AirSample& air);
    // Start from a pre-flight alignment (the sensors' published one) on the first step with a valid fix: attitude,
    // sensor and field errors and their 1-sigma from it (the attitude sigma on every axis), position and velocity from
    // the fix.
    void start(double t_s, const Alignment& align, const ImuSample& imu, const GnssSample& fix,
               const AirSample* air = nullptr);
    [[nodiscard]] bool started() const { return started_; }

    // One step after the start: propagation with this step's IMU sample, the magnetometer every mag_period_steps,
    // the air data every air_period_steps (HandOver::kNever, when given), the fix if there is one (ignored once
    // handed over). True on the one step at which the alignment is handed over (then it stops); with the hand-over
    // at the GNSS loss or never, never true (hand_over() ends the GNSS-aided phase).
    bool step(double t_s, const ImuSample& imu, const MagSample& mag, const GnssSample* fix,
              const AirSample* air = nullptr);
    // The GNSS loss: HandOver::kAtGnssLoss ends the estimator (handed over from this step on); HandOver::kNever marks
    // the step and goes on without fixes.
    void hand_over(double t_s);
    // Not finished: waiting for its start, or stepping (unless HandOver::kNever, until handed over).
    [[nodiscard]] bool running() const { return !handed_over_ || mode_ == HandOver::kNever; }
    [[nodiscard]] HandOver mode() const { return mode_; }
    [[nodiscard]] bool aligned() const { return aligned_; }
    [[nodiscard]] double t_aligned_s() const { return t_aligned_s_; }
    [[nodiscard]] bool handed_over() const { return handed_over_; }
    [[nodiscard]] double t_handed_over_s() const { return t_handed_over_s_; }

    [[nodiscard]] double tilt_sigma_rad() const;
    [[nodiscard]] double heading_sigma_rad() const;
    // The estimates and their 1-sigma, as the sensors' pre-flight alignment (att_sigma_rad: the larger of the tilt
    // and heading sigmas).
    [[nodiscard]] Alignment alignment() const;
    // The aligner's attitude as an attitude filter's output (nav_att publishes it until the hand-over): the angular
    // rate of its last propagation, the sensor and field errors, the NED-side attitude sigmas.
    [[nodiscard]] AttitudeEstimate estimate(std::uint64_t k, double t_s) const;
    // The attitude filter's start at the GNSS loss: the estimates and the joint covariance of the attitude, gyro,
    // magnetometer and field errors (nav_types.hpp).
    [[nodiscard]] AttitudeHandover handover() const;
    [[nodiscard]] const Quat& q_nb() const { return q_nb_; }
    // HandOver::kNever: the slowly varying wind (NED, without the turbulence) and the air-data offsets (TAS [m/s],
    // AOA, AOS [rad]); zero in the other modes.
    [[nodiscard]] const Vec3& wind_n_mps() const { return wind_n_; }
    [[nodiscard]] const Vec3& air_offsets() const { return b_air_; }
    [[nodiscard]] Vec3 air_offsets_sigma() const;

private:
    void propagate(const ImuSample& imu);
    void update_mag(const MagSample& mag);
    void update_fix(const GnssSample& fix);
    void update_air(const AirSample& air);
    void inject(const filters::Vec<kN>& dx);
    void start_common(double t_s, const GnssSample& fix, const AirSample* air);
    // The estimates the attitude filter's state holds (shared by estimate() and handover()).
    [[nodiscard]] AttitudeState state() const { return {q_nb_, w_nb_b_, e_gyr_, e_mag_, b_dev_}; }

    InFlightAlignerSettings s_{};
    double dt_s_{0.01};
    HandOver mode_{HandOver::kAtAlignment};
    filters::Vec<kN> q_diag_{filters::Vec<kN>::Zero()};  // per-step process noise, from the settings and dt
    bool started_{false};
    bool aligned_{false};
    double t_aligned_s_{0.0};
    bool handed_over_{false};
    double t_handed_over_s_{0.0};
    double t_criteria_met_s_{0.0};
    bool criteria_met_{false};
    std::uint64_t steps_{0};
    Quat q_nb_{Quat::Identity()};
    Vec3 v_n_{Vec3::Zero()};
    Vec3 w_nb_b_{Vec3::Zero()};
    double lon_rad_{0.0}, lat_rad_{0.0}, h_m_{0.0};
    Vec3 e_gyr_{Vec3::Zero()}, e_acc_{Vec3::Zero()}, e_mag_{Vec3::Zero()}, b_dev_{Vec3::Zero()}, wind_n_{Vec3::Zero()};
    Vec3 turb_n_{Vec3::Zero()}, b_air_{Vec3::Zero()};  // turbulence (NED) and air-data offsets (TAS, AOA, AOS)
    double turb_decay_{1.0};                          // exp(-dt / turb_tau_s)
    Eigen::Matrix3d m_mag_{Eigen::Matrix3d::Zero()};
    filters::SqMat<kN> p_{filters::SqMat<kN>::Zero()};
};

// One step of a component that runs the aligner: starts it on the first step whose IMU, magnetometer and air data
// samples pass the input checks with a valid fix (from `published` when given: the sensors' pre-flight alignment),
// steps it after (an IMU or magnetometer sample failing its check skips the step, air data failing its check skips
// the air-data update). True on the hand-over step at the alignment.
bool step_in_flight_aligner(InFlightAligner& a, double t_s, const ImuSample& imu, const MagSample& mag,
                            const GnssSample& gnss, const AirSample& air, const Alignment* published = nullptr);

}  // namespace gdnav::nav
