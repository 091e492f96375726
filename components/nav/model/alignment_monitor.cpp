// `alignment_check` keys (all optional; ranges):
//   tilt_sigma_max_deg [0.001, 10] (0.3)   yaw_sigma_max_deg [0.001, 30] (1.0)
//   nis_window_s [1, 600] (20)             nis_mean_max [1, 1000] (12)          hold_s [0, 600] (10)
//   accel_noise_mps2 [1e-4, 10] (0.3)      fix_period_s [0.01, 60] (1)
//   accel_bias_walk_mps2_rts [0, 1] (1e-4) tilt_walk_rad_rts [0, 1] (1e-5)
#include "alignment_monitor.hpp"

#include <algorithm>
#include <cmath>

namespace gdnav::nav {

using config::Range;

AlignmentCriteria parse_alignment_criteria(const config::Config& c) {
    AlignmentCriteria a;
    a.tilt_sigma_max_rad = math::deg2rad(c.get_double("tilt_sigma_max_deg", 0.3, Range{0.001, 10.0}));
    a.yaw_sigma_max_rad = math::deg2rad(c.get_double("yaw_sigma_max_deg", 1.0, Range{0.001, 30.0}));
    a.nis_window_s = c.get_double("nis_window_s", a.nis_window_s, Range{1.0, 600.0});
    a.nis_mean_max = c.get_double("nis_mean_max", a.nis_mean_max, Range{1.0, 1000.0});
    a.hold_s = c.get_double("hold_s", a.hold_s, Range{0.0, 600.0});
    a.accel_noise_mps2 = c.get_double("accel_noise_mps2", a.accel_noise_mps2, Range{1e-4, 10.0});
    a.fix_period_s = c.get_double("fix_period_s", a.fix_period_s, Range{0.01, 60.0});
    a.accel_bias_walk_mps2_rts = c.get_double("accel_bias_walk_mps2_rts", a.accel_bias_walk_mps2_rts, Range{0.0, 1.0});
    a.tilt_walk_rad_rts = c.get_double("tilt_walk_rad_rts", a.tilt_walk_rad_rts, Range{0.0, 1.0});
    c.finish();
    return a;
}

void AlignmentMonitor::start(double tilt_sigma_rad, double acc_bias_sigma_mps2) {
    p_.setZero();
    p_(0, 0) = p_(1, 1) = tilt_sigma_rad * tilt_sigma_rad;
    p_(2, 2) = p_(3, 3) = acc_bias_sigma_mps2 * acc_bias_sigma_mps2;
    started_ = true;
}

double AlignmentMonitor::tilt_sigma_rad() const { return std::sqrt(std::max({p_(0, 0), p_(1, 1), 0.0})); }

double AlignmentMonitor::nis_mean() const {
    if (fixes_.empty()) return 0.0;
    double s = 0.0;
    for (const auto& f : fixes_) s += f.second;
    return s / static_cast<double>(fixes_.size());
}

void AlignmentMonitor::step(double t_s, const math::Vec3& f_b, const math::Quat& q_nb, double yaw_sigma_rad,
                            const double* gnss_d2, bool gnss_denied) {
    if (!started_) return;
    yaw_sigma_rad_ = yaw_sigma_rad;
    // Random walks, then the joint update of the horizontal acceleration (zero innovation: only P is needed).
    const double qt = c_.tilt_walk_rad_rts * c_.tilt_walk_rad_rts * dt_s_;
    const double qe = c_.accel_bias_walk_mps2_rts * c_.accel_bias_walk_mps2_rts * dt_s_;
    p_.diagonal() += filters::Vec<4>(qt, qt, qe, qe);
    if (!gnss_denied) {
        const math::Mat3 r = q_nb.toRotationMatrix();
        const math::Vec3 f_n = r * f_b;
        filters::Mat<2, 4> h;
        h << 0.0, f_n.z(), -r(0, 0), -r(0, 1),
             -f_n.z(), 0.0, -r(1, 0), -r(1, 1);
        const double var = c_.accel_noise_mps2 * c_.accel_noise_mps2 * (c_.fix_period_s / dt_s_);
        filters::Vec<4> x = filters::Vec<4>::Zero();
        (void)filters::joseph_update_diag<4, 2>(x, p_, filters::Vec<2>::Zero(), h, filters::Vec<2>::Constant(var));
    }
    if (gnss_d2 != nullptr) {
        if (fixes_.empty()) t_first_fix_s_ = t_s;
        fixes_.emplace_back(t_s, *gnss_d2);
    }
    while (!fixes_.empty() && fixes_.front().first < t_s - c_.nis_window_s + 1e-9) fixes_.pop_front();
    if (aligned_) return;
    const bool window_full = !fixes_.empty() && t_s - t_first_fix_s_ >= c_.nis_window_s - 1e-9;
    const bool met = !gnss_denied && window_full && tilt_sigma_rad() <= c_.tilt_sigma_max_rad &&
                     yaw_sigma_rad <= c_.yaw_sigma_max_rad && nis_mean() <= c_.nis_mean_max;
    if (met && !met_) t_met_since_s_ = t_s;
    met_ = met;
    if (met_ && t_s - t_met_since_s_ >= c_.hold_s - 1e-9) {
        aligned_ = true;
        t_aligned_s_ = t_s;
    }
}

}  // namespace gdnav::nav
