#pragma once
// Attitude filter (paper "Attitude Filter"; docs/navigation.md "Attitude filter"). Model, observation
// equations and Jacobians: attitude_model.hpp. A plain additive EKF on 16 states with the quaternion as 4 raw
// components, renormalised after the prediction and after the update (reference formulation, kept so results are
// comparable with the paper; the covariance is not projected).
//
// Inputs per step k:  ImuSample (gyro w~_ib_b, accelerometer f~_ib_b), MagSample (B~_b) of step k, and the
//                     PositionEstimate of step k-1 (source of p_n: position, ground velocity, wind, E_acc).
// Output:             AttitudeEstimate (q_nb, Euler 3-2-1, w_nb_b, E_gyr, E_mag, B_dev, 1-sigma attitude about N).
// Step:  A = df/dx at x+(k-1), Phi = I + A dt + (A dt)^2/2 (`transition_order`), x-(k) = x+ + dt f(x+), normalise q,
//        P- = Phi P Phi^T + Q;  y = [w~, f~, B~], Joseph update with H at x-, normalise q.
// Variant (`attitude.specific_force` of a variant file): baseline | zero_fb_derivatives | zero_fn_derivatives;
// only the coupling term of the specific-force observation differs (att::coupling_velocity_n).
// Variant `attitude.filter` (optional, default additive): additive (above, the paper's) | error_state (the
// multiplicative error-state EKF of eskf_attitude.hpp on the same nominal state, model and observations).
// Tuning (config/nav/tuning.yaml, `attitude`): Q and R as the reference "configuration #4" (docs/navigation.md
// "Attitude filter"), initialisation as nav_init.hpp.
// Input checks (input_checks.hpp): an ImuSample (rows gyro + accelerometer) or MagSample (rows magnetometer) that is
//   non-finite or out of range is rejected and counted, and the update uses the other sample's rows only (propagate
//   only when both are rejected). A rejected previous PositionEstimate (p_n source) is replaced by the last good one
//   (or, before any, the accelerometer rows are skipped). The state never sees a rejected value.
#include <cstdint>

#include "attitude_model.hpp"
#include "eskf_attitude.hpp"
#include "config/config.hpp"
#include "input_checks.hpp"
#include "math/rotation.hpp"
#include "nav_init.hpp"
#include "random/stream.hpp"

namespace gdnav::nav {

// Explicit initial estimate and its diagonal 1-sigma (attitude as a rotation angle, or as a quaternion variance).
struct AttitudeInit : AttitudeState {
    double att_sigma_rad{0.0};  // if > 0: P_qq = (sigma^2/4) Xi(q) Xi(q)^T (isotropic angle error)
    // If > 0 (with att_sigma_rad > 0): the angle error about D has this sigma and att_sigma_rad is the tilt's (about
    // N and E): P_qq = (1/4) Xi(q) R^T diag(tilt^2, tilt^2, heading^2) R Xi(q)^T.
    double heading_sigma_rad{0.0};
    double q_p0{0.0};           // else:   P_qq = q_p0 I4 (reference)
    Vec3 w_nb_sigma_rps{Vec3::Zero()};
    Vec3 gyr_bias_sigma_rps{Vec3::Zero()};
    Vec3 mag_bias_sigma_nT{Vec3::Zero()};
    Vec3 b_dev_sigma_nT{Vec3::Zero()};
};

enum class AttitudeFormulation { kAdditive, kErrorState };

class AttitudeFilter {
public:
    struct Tuning {
        double dt_s{0.01};
        int transition_order{2};
        att::StateVec q_diag = att::StateVec::Zero();
        att::MeasVec r_diag = att::MeasVec::Zero();
        att::SpecificForceModel model{att::SpecificForceModel::kBaseline};
        AttitudeFormulation formulation{AttitudeFormulation::kAdditive};
        InitMode init_mode{InitMode::kMeasurements};
        MeasurementInitSigmas init_sigmas;
        double align_q_p0{1e-8};  // alignment mode: P0 per quaternion component (reference); 0: use the sigma

        double gyr_noise_var{5.63e-7};  // per-sample gyro white-noise variance, added to P0 of w_nb
    };

    // tuning: `attitude` section of config/nav/tuning.yaml; variant: `attitude` section of a variant file.
    // The filter draws nothing today; the stream stays in the interface so that a variant with random draws
    // keeps the same wiring.
    void configure(const config::Config& tuning, const config::Config& variant, rnd::Stream stream);
    void configure(const Tuning& tuning, rnd::Stream stream);

    // Initialisation per `init.mode`. measurements: from the first IMU/mag samples, the air data estimate and the
    // first GNSS fix (position for the model field and declination). alignment: needs the published alignment
    // (throws otherwise).
    AttitudeEstimate initialize(std::uint64_t k, double t_s, const ImuSample& imu, const MagSample& mag,
                                const AirDataEstimate& air, const GnssSample& gnss,
                                const Alignment* align = nullptr);
    AttitudeEstimate initialize(std::uint64_t k, double t_s, const AttitudeInit& init);
    // Starts again from an alignment made in flight (in_flight_aligner.hpp), as `init.mode: alignment` starts from
    // the sensors' published one: the same P0 policy (align_q_p0, else the alignment's sigma).
    AttitudeEstimate realign(std::uint64_t k, double t_s, const ImuSample& imu, const Alignment& align);
    // Starts from a joint GNSS/INS estimator's state and the joint covariance of its errors (variant
    // gnss_calibration_handover, at the GNSS loss): P = T P_err T^T + the gyro white noise on w_nb, with T carrying
    // the NED-side attitude error to the quaternion (dq = 0.5 Xi(q) R^T phi) and the gyro error to w_nb
    // (dw_nb = -dE_gyr), so the correlations between heading, gyro and field errors are kept.
    AttitudeEstimate hand_over(std::uint64_t k, double t_s, const AttitudeHandover& h);

    AttitudeEstimate step(std::uint64_t k, double t_s, const ImuSample& imu, const MagSample& mag,
                          const PositionEstimate& pos_prev);

    // A heading observation (e.g. yaw_gsf.hpp's GNSS yaw) with variance yaw_var_rad2: a scalar Joseph update of the
    // current state on the NED-side yaw angle (additive: the D row of att_error_jacobian on q; error-state: dtheta_D),
    // then the usual normalisation / injection. Returns the NIS. Used only by runs that configure it.
    double fuse_yaw(double yaw_rad, double yaw_var_rad2);

    // Samples rejected by the input checks since configure().
    struct Rejections {
        std::uint64_t imu{0};
        std::uint64_t mag{0};
        std::uint64_t position{0};  // previous PositionEstimate (p_n source)
        [[nodiscard]] std::uint64_t total() const { return imu + mag + position; }
    };
    [[nodiscard]] const Rejections& rejections() const { return rej_; }

    [[nodiscard]] bool initialized() const { return initialized_; }
    [[nodiscard]] const att::StateVec& state() const { return x_; }
    [[nodiscard]] const att::StateCov& covariance() const { return p_; }  // additive formulation only
    [[nodiscard]] const eskf::ErrCov& error_covariance() const { return pe_; }  // error_state formulation only
    [[nodiscard]] const Tuning& tuning() const { return tun_; }
    [[nodiscard]] double last_nis() const { return last_nis_; }
    [[nodiscard]] Quat estimate_q() const { return math::from_wxyz(x_.segment<4>(att::kQ)); }
    // 3x3 covariance of the attitude error about N axes (small angles), from the quaternion block of P.
    [[nodiscard]] Eigen::Matrix3d attitude_covariance_n() const;

private:
    AttitudeEstimate output(std::uint64_t k, double t_s) const;
    // x = s (quaternion normalised), P untouched; returns the normalised quaternion.
    Quat set_state(const AttitudeState& s);
    void normalise_quaternion();
    void step_error_state(bool imu_good, bool mag_good, const att::MeasVec& y, const att::PnVector& pn);
    [[nodiscard]] AttitudeInit init_from_alignment(const ImuSample& imu, const Alignment& align) const;

    Tuning tun_;
    rnd::Stream stream_;
    att::StateVec x_ = att::StateVec::Zero();
    att::StateCov p_ = att::StateCov::Zero();
    eskf::ErrCov pe_ = eskf::ErrCov::Zero();
    eskf::ErrVec qe_diag_ = eskf::ErrVec::Zero();
    double last_nis_{0.0};
    Rejections rej_;
    PositionEstimate pos_held_;  // last PositionEstimate that passed the checks
    bool pos_held_valid_{false};
    bool initialized_{false};
};

// Parses `specific_force: baseline | zero_fb_derivatives | zero_fn_derivatives`.
att::SpecificForceModel parse_specific_force_model(const config::Config& variant);
// Parses the optional `filter: additive | error_state` (default additive).
AttitudeFormulation parse_attitude_formulation(const config::Config& variant);

}  // namespace gdnav::nav
