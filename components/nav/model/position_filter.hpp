#pragma once
// Position filter (paper "Position Filter"; reference filter_gps01 + filter_pos + pos02B and the comparison
// variants, models-nav.md §5, §7, §8).
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
// Variants (`position` section of a variant file): horizontal: frozen_wind | double_integration | wind_integration;
//   vertical: pressure | integration | airspeed_integration.
// Longitudes are output in (-pi, pi]; longitude innovations are wrapped.
#include <cstdint>

#include "config/config.hpp"
#include "denied_rules.hpp"
#include "gnss_aided_model.hpp"
#include "gnss_loss_monitor.hpp"
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

    // The runtime declared the GNSS publisher dead: the next step runs GNSS-denied.
    void set_gnss_publisher_dead() { monitor_.set_publisher_dead(); }

    [[nodiscard]] bool initialized() const { return initialized_; }
    [[nodiscard]] bool gnss_denied() const { return monitor_.denied(); }
    [[nodiscard]] const Tuning& tuning() const { return tun_; }
    [[nodiscard]] const aided::StateVec& aided_state() const { return x_; }
    [[nodiscard]] const aided::StateCov& aided_covariance() const { return p_; }
    [[nodiscard]] const filters::Vec<kNd>& denied_state() const { return xd_; }

private:
    void aided_step(const ImuSample& imu, const GnssSample& gnss, bool fix, const AirDataEstimate& air,
                    const AttitudeEstimate& att);
    void enter_denied();
    void denied_step(const ImuSample& imu, const AirDataEstimate& air, const AttitudeEstimate& att);
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
    double dp_lp_{0.0};
    Vec3 wind_at_fix_{Vec3::Zero()};
    double dp_at_fix_{0.0};
    // denied phase
    filters::Vec<kNd> xd_ = filters::Vec<kNd>::Zero();
    filters::SqMat<kNd> pd_ = filters::SqMat<kNd>::Zero();
    denied::DeniedState ds_;
    bool initialized_{false};
    bool lost_event_{false};
};

denied::HorizontalRule parse_horizontal_rule(const config::Config& variant);
denied::VerticalRule parse_vertical_rule(const config::Config& variant);

}  // namespace gdnav::nav
