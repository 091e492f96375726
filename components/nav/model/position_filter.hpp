#pragma once
// Position filter (paper "Position Filter" and its comparison variants; docs/navigation.md "Position filter").
//
// Inputs per step k: ImuSample (accelerometer f~), GnssSample (valid at 1 Hz while signals exist), the
//   AirDataEstimate and AttitudeEstimate of the same step k.
// Output: PositionEstimate (geodetic position, ground velocity, wind, Hp, dp, dT, E_acc, gnss_denied, and the
//   gnss_lost_event flag on the switching step). The attitude filter reads it at k+1 as its p_n source.
//
// GNSS-aided phase (dual-rate 12-state EKF, gnss_aided_model.hpp): propagate with the current attitude; update with
//   f~ every step and additionally with GNSS velocity and position on fix steps. Then GNSS-based estimates
//   (first-order low pass y <- (1 - a) y + a u, a = dt/(T_f + dt), T_f = 3 s, started with the first value):
//     wind:  u = v_n - R(q) v_tas_b(v_tas, aoa, aos)
//     dp:    u = dp(H = R_E h/(R_E + h), Hp, dT)   (INSA inverse, nav_earth.hpp)
// GNSS loss (gnss_loss_monitor.hpp): > 1.5 s of simulated time without a valid fix, or set_gnss_publisher_dead().
// GNSS-denied phase: a 6-state EKF [f_ib_b, E_acc] (static, y = f + E_acc, H = [I I]) started from the aided
//   filter's sub-state and covariance blocks; wind and dp frozen at their values of the last valid fix; position,
//   velocity, wind and altitude by the variant's rules (denied_rules.hpp), seeded with the aided filter's last state.
// GNSS integrity (tuning `position.gnss_integrity`, docs/navigation.md "GNSS integrity and re-acquisition"):
//   chi-square gate: on a fix step of the aided phase, the GNSS part of the innovation (v_n, lon, lat, h; lon/lat
//     turned into metres) and its covariance S = H P- H^T + R give d2 = r^T S^-1 r (6 dof); a fix with
//     d2 > gate_chi2_6dof is rejected (counted; the step updates with the accelerometer only). After
//     max_consecutive_rejections rejections in a row the fix source is declared untrusted and the filter goes
//     GNSS-denied (event reason kUntrusted): coasting on a spoofed or broken source is worse than dead reckoning.
//   re-acquisition (denied phase, reacquire_fixes > 0; 0 keeps the reference's one-way switch): a fix counts towards
//     re-acquisition when it passes the input checks, lies within reacquire_dr_bound_m + reacquire_dr_bound_rate_mps
//     x (time since the switch to denied) of the dead-reckoned position (horizontal), and is consistent with the
//     previous counted fix (<= gnss_loss_timeout_s earlier; position difference minus the mean fix velocity x dt,
//     chi-square with 3 dof <= reacquire_consistency_chi2_3dof under the fix sigmas). After reacquire_fixes such fixes
//     in a row the aided EKF is reset: position and velocity from the last fix with P0 = the fix variances (as at
//     initialisation: the fix, not the dead-reckoned estimate, is the prior, so no inflation for the denied-phase
//     error is needed), f and E_acc with their covariance from the denied 6-state EKF, the GNSS wind and dp low
//     passes restarted from their instant values. The step carries gnss_reacquired_event = true.
// Input checks (input_checks.hpp): a rejected ImuSample skips the accelerometer rows (propagation only without a
//   fix), a rejected fix is not a fix, a rejected AirDataEstimate or AttitudeEstimate is replaced by the last good
//   one. Counted per input (rejections()).
// Variants (`position` section of a variant file): horizontal: frozen_wind | double_integration | wind_integration;
//   vertical: pressure | integration | airspeed_integration.
// Longitudes are output in (-pi, pi]; longitude innovations are wrapped.
#include <cstdint>
#include <optional>

#include "config/config.hpp"
#include "denied_rules.hpp"
#include "gnss_aided_model.hpp"
#include "gnss_loss_monitor.hpp"
#include "input_checks.hpp"
#include "nav_init.hpp"
#include "random/stream.hpp"

namespace gdnav::nav {

class PositionFilter {
public:
    static constexpr int kNd = 6;  // GNSS-denied EKF [f, E_acc]
    struct Tuning {
        double dt_s{0.01};
        int transition_order{2};
        Vec3 q_pos_m2{Vec3::Constant(1e-6)};  // per step, N E D
        double q_v_m2ps2{1e-5};
        double q_f_m2ps4{1e-4};
        double q_acc_err_m2ps4{4.71e-14};
        double r_acc_m2ps4{2.33e-5};
        double gnss_v_sigma_mps{0.0741};
        double gnss_hor_sigma_m{2.12};
        double gnss_ver_sigma_m{4.25};
        double lowpass_time_constant_s{3.0};
        double gnss_loss_timeout_s{1.5};
        InitMode init_mode{InitMode::kMeasurements};
        double init_acc_bias_sigma_mps2{0.157};  // measurements mode
        denied::HorizontalRule horizontal{denied::HorizontalRule::kFrozenWind};
        denied::VerticalRule vertical{denied::VerticalRule::kPressure};
        // Variant `frozen_wind_average_s` (optional): > 0 freezes for the denied phase a low pass of the GNSS-based
        // wind with this time constant instead of the 3 s one (the mean wind rather than the current gust).
        double frozen_wind_average_s{0.0};
        // Variant `wind_at_loss` (optional): own (the wind above) | gnss_ins (the joint GNSS/INS estimator's wind and
        // air-data offsets, set_gnss_ins_calibration; docs/navigation.md, "Keeping the GNSS calibration").
        bool wind_from_gnss_ins{false};
        // GNSS integrity (gnss_integrity section)
        double gate_chi2_6dof{40.0};
        int gate_max_consecutive_rejections{5};
        int reacquire_fixes{5};
        double reacquire_consistency_chi2_3dof{30.0};
        double reacquire_dr_bound_m{100.0};
        double reacquire_dr_bound_rate_mps{3.0};
    };

    // Why the filter went GNSS-denied (the last switch).
    enum class DeniedReason { kNone, kTimeout, kPublisherDead, kUntrusted };

    // Samples rejected since configure(), per input, and the GNSS integrity counters.
    struct Rejections {
        std::uint64_t imu{0};             // ImuSample failing the input checks
        std::uint64_t gnss_invalid{0};    // fix_valid sample with non-finite or out-of-range values
        std::uint64_t air{0};             // AirDataEstimate failing the checks (last good one used)
        std::uint64_t attitude{0};        // AttitudeEstimate failing the checks (last good one used)
        std::uint64_t gnss_gate{0};       // fixes rejected by the chi-square gate (aided phase)
        std::uint64_t gnss_reacquire{0};  // fixes refused for re-acquisition (denied phase: too far from the dead-
                                          // reckoned position, or inconsistent with the previous fix)
        [[nodiscard]] std::uint64_t total() const {
            return imu + gnss_invalid + air + attitude + gnss_gate + gnss_reacquire;
        }
    };

    // tuning: `position` section of config/nav/tuning.yaml; variant: `position` section of a variant file.
    // The filter draws nothing today; the stream stays in the interface so that a variant with random draws
    // keeps the same wiring.
    void configure(const config::Config& tuning, const config::Config& variant, rnd::Stream stream);
    void configure(const Tuning& tuning, rnd::Stream stream);

    // Initialisation at the first valid GNSS fix (throws if gnss.fix_valid is false). init.mode alignment needs
    // the published alignment (E_acc at t0 and its sigma).
    PositionEstimate initialize(std::uint64_t k, double t_s, const ImuSample& imu, const GnssSample& gnss,
                                const AirDataEstimate& air, const AttitudeEstimate& att,
                                const Alignment* align = nullptr);
    PositionEstimate initialize(std::uint64_t k, double t_s, const ImuSample& imu, const GnssSample& gnss,
                                const AirDataEstimate& air, const AttitudeEstimate& att, const Vec3& acc_err0,
                                const Vec3& acc_err_sigma0);

    PositionEstimate step(std::uint64_t k, double t_s, const ImuSample& imu, const GnssSample& gnss,
                          const AirDataEstimate& air, const AttitudeEstimate& att);

    // With `wind_at_loss: gnss_ins`: the joint estimator's slow wind (NED) and air-data offsets (TAS [m/s], AOA, AOS
    // [rad]), given before each step; what was given before the GNSS loss is kept through the denied phase (given
    // while denied, it is ignored), the offsets taken off the air data there.
    void set_gnss_ins_calibration(const Vec3& wind_n_mps, const Vec3& air_offsets) {
        if (tun_.wind_from_gnss_ins && !monitor_.denied()) gnss_ins_ = GnssInsCalibration{wind_n_mps, air_offsets};
    }
    [[nodiscard]] bool has_gnss_ins_calibration() const { return gnss_ins_.has_value(); }

    // The runtime declared the GNSS publisher dead: the next step runs GNSS-denied.
    void set_gnss_publisher_dead() { monitor_.set_publisher_dead(); }
    // The GNSS publisher is alive again (restarted): its fixes may re-acquire.
    void set_gnss_publisher_alive() { monitor_.set_publisher_alive(); }

    [[nodiscard]] bool initialized() const { return initialized_; }
    [[nodiscard]] bool gnss_denied() const { return monitor_.denied(); }
    [[nodiscard]] DeniedReason denied_reason() const { return denied_reason_; }
    [[nodiscard]] const Rejections& rejections() const { return rej_; }
    [[nodiscard]] std::uint64_t reacquisitions() const { return reacquisitions_; }
    [[nodiscard]] std::uint64_t gate_accepted() const { return gate_accepted_; }
    // Largest chi-square value of an accepted fix, and the value of the last gated fix (accepted or not).
    [[nodiscard]] double gate_d2_max_accepted() const { return gate_d2_max_accepted_; }
    [[nodiscard]] double gate_d2_last() const { return gate_d2_last_; }
    [[nodiscard]] const Tuning& tuning() const { return tun_; }
    [[nodiscard]] const aided::StateVec& aided_state() const { return x_; }
    [[nodiscard]] const aided::StateCov& aided_covariance() const { return p_; }
    [[nodiscard]] const filters::Vec<kNd>& denied_state() const { return xd_; }

private:
    // Returns false when the fix was rejected by the chi-square gate.
    bool aided_step(const ImuSample& imu, bool imu_good, const GnssSample& gnss, bool fix, const AirDataEstimate& air,
                    const AttitudeEstimate& att);
    void enter_denied(double t_s);
    void denied_step(const ImuSample& imu, bool imu_good, const AirDataEstimate& air, const AttitudeEstimate& att);
    void reacquisition_candidate(double t_s, const GnssSample& gnss, const AirDataEstimate& air,
                                 const AttitudeEstimate& att);
    void reacquire(double t_s, const GnssSample& gnss, const AirDataEstimate& air, const AttitudeEstimate& att);
    void set_fix_covariance(double lat_rad, double h_m);
    [[nodiscard]] Vec3 wind_instant(const AirDataEstimate& air, const AttitudeEstimate& att) const;
    [[nodiscard]] double dp_instant(const AirDataEstimate& air) const;
    [[nodiscard]] PositionEstimate output(std::uint64_t k, double t_s, const AirDataEstimate& air) const;

    Tuning tun_;
    rnd::Stream stream_;
    GnssLossMonitor monitor_;
    // aided phase
    aided::StateVec x_ = aided::StateVec::Zero();
    aided::StateCov p_ = aided::StateCov::Zero();
    Vec3 wind_lp_{Vec3::Zero()};
    Vec3 wind_avg_{Vec3::Zero()};  // long low pass of the GNSS-based wind (frozen_wind_average_s > 0)
    double dp_lp_{0.0};
    Vec3 wind_at_fix_{Vec3::Zero()};
    double dp_at_fix_{0.0};
    struct GnssInsCalibration {
        Vec3 wind_n_mps;
        Vec3 air_offsets;  // TAS [m/s], AOA, AOS [rad]
    };
    std::optional<GnssInsCalibration> gnss_ins_;  // wind_at_loss: gnss_ins, the last given before the loss
    // denied phase
    filters::Vec<kNd> xd_ = filters::Vec<kNd>::Zero();
    filters::SqMat<kNd> pd_ = filters::SqMat<kNd>::Zero();
    denied::DeniedState ds_;
    bool initialized_{false};
    bool lost_event_{false};
    // integrity and input checks
    Rejections rej_;
    AirDataEstimate air_held_;      // last AirDataEstimate that passed the checks
    AttitudeEstimate att_held_;     // last AttitudeEstimate that passed the checks
    DeniedReason denied_reason_{DeniedReason::kNone};
    bool reacquired_event_{false};
    int consecutive_rejections_{0};
    double t_denied_s_{0.0};
    int candidate_count_{0};        // consecutive fixes counted towards re-acquisition
    double candidate_t_s_{0.0};
    GnssSample candidate_;
    std::uint64_t reacquisitions_{0};
    std::uint64_t gate_accepted_{0};
    double gate_d2_max_accepted_{0.0};
    double gate_d2_last_{0.0};
};

denied::HorizontalRule parse_horizontal_rule(const config::Config& variant);
denied::VerticalRule parse_vertical_rule(const config::Config& variant);

}  // namespace gdnav::nav
