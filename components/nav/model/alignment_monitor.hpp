#pragma once
// In-flight alignment monitor (docs/navigation.md, "In-flight alignment"): decides from the navigation filters' own
// estimates, covariances and innovations — never from the truth — when the estimate is good enough to fly on.
//
// Why a model of its own: the attitude filter takes E_acc from the position filter and the position filter takes the
// attitude from the attitude filter, each as if exact, so neither covariance holds the tilt / accelerometer-bias
// ambiguity of straight and level flight (both shrink while the pair stays wrong). The monitor keeps the joint
// covariance of x = [tilt_N, tilt_E, E_acc_x, E_acc_y] (rad, rad, m/s^2, m/s^2) under the only thing that separates
// them, the GNSS-observed horizontal acceleration:
//   delta a_NE = (tilt x f_n)_NE - R(q)_(NE,xy) E_acc_xy,    f_n = R(q) f~_b   (q_true = Exp(tilt) q, as the metrics)
// one linear update per step with noise accel_noise_mps2^2 * (fix period / dt) (the information of one GNSS
// velocity difference per fix period, spread over its steps), and random-walk noise on every state
// (accel_bias_walk_mps2_rts, tilt_walk_rad_rts). Its prior is the filters' initial covariance (attitude sigma N/E,
// the position filter's P of E_acc x, y). With a constant heading H has rank 2 and the tilt sigma stays near
// E_acc_sigma / g; a turn rotates R and makes all four observable.
//
// Aligned when, for hold_s without a break, while GNSS-aided:
//   tilt sigma (sqrt of the larger of the two tilt variances) <= tilt_sigma_max_deg,
//   the attitude filter's yaw sigma (about D)                  <= yaw_sigma_max_deg,
//   the mean GNSS innovation d2 (6 dof) over the last nis_window_s of fixes <= nis_mean_max (and the window full).
// Latched once declared; never declared once GNSS-denied.
#include <cstdint>
#include <deque>
#include <utility>

#include "config/config.hpp"
#include "filters/ekf.hpp"
#include "math/rotation.hpp"

namespace gdnav::nav {

struct AlignmentCriteria {
    double tilt_sigma_max_rad{math::deg2rad(0.3)};
    double yaw_sigma_max_rad{math::deg2rad(1.0)};
    double nis_window_s{20.0};
    double nis_mean_max{12.0};
    double hold_s{10.0};
    double accel_noise_mps2{0.3};
    double fix_period_s{1.0};
    double accel_bias_walk_mps2_rts{1e-4};
    double tilt_walk_rad_rts{1e-5};
};

// Reads the `alignment_check` section (keys and ranges in alignment_monitor.cpp); ConfigError naming the key.
AlignmentCriteria parse_alignment_criteria(const config::Config& c);

class AlignmentMonitor {
public:
    AlignmentMonitor() = default;
    AlignmentMonitor(const AlignmentCriteria& c, double dt_s) : c_(c), dt_s_(dt_s) {}

    // Prior from the filters at their initialisation.
    void start(double tilt_sigma_rad, double acc_bias_sigma_mps2);
    // One step: specific force (body), attitude estimate, the attitude filter's yaw sigma, the GNSS d2 of a fix
    // accepted this step (if any), and whether the position filter runs GNSS-denied.
    void step(double t_s, const math::Vec3& f_b_mps2, const math::Quat& q_nb, double yaw_sigma_rad,
              const double* gnss_d2, bool gnss_denied);

    [[nodiscard]] bool started() const { return started_; }
    [[nodiscard]] bool aligned() const { return aligned_; }
    [[nodiscard]] double t_aligned_s() const { return t_aligned_s_; }
    [[nodiscard]] double tilt_sigma_rad() const;
    [[nodiscard]] double yaw_sigma_rad() const { return yaw_sigma_rad_; }
    [[nodiscard]] double nis_mean() const;
    [[nodiscard]] const filters::SqMat<4>& covariance() const { return p_; }

private:
    AlignmentCriteria c_;
    double dt_s_{0.01};
    filters::SqMat<4> p_ = filters::SqMat<4>::Zero();
    std::deque<std::pair<double, double>> fixes_;  // (t, d2) within the window
    double t_first_fix_s_{0.0};
    double yaw_sigma_rad_{0.0};
    double t_met_since_s_{0.0};
    bool met_{false};
    bool started_{false};
    bool aligned_{false};
    double t_aligned_s_{0.0};
};

}  // namespace gdnav::nav
