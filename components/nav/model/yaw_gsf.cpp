// `yaw_from_gnss` estimator keys (optional; ranges): models [3, 16] (5), accel_noise_mps2 [0.01, 10] (1),
// rate_noise_rps [1e-4, 1] (0.01), velocity_noise_mps [0.01, 10] (0.5).
#include "yaw_gsf.hpp"

#include <algorithm>
#include <cmath>

namespace gdnav::nav {

using config::Range;

YawGsfSettings parse_yaw_gsf(const config::Config& c) {
    YawGsfSettings s;
    s.models = static_cast<int>(c.get_int("models", s.models, 3, 16));
    s.accel_noise_mps2 = c.get_double("accel_noise_mps2", s.accel_noise_mps2, Range{0.01, 10.0});
    s.rate_noise_rps = c.get_double("rate_noise_rps", s.rate_noise_rps, Range{1e-4, 1.0});
    s.velocity_noise_mps = c.get_double("velocity_noise_mps", s.velocity_noise_mps, Range{0.01, 10.0});
    return s;
}

void YawGsf::start(const math::Vec3& v_n) {
    models_.clear();
    const double spread = 2.0 * math::kPi / s_.models;
    for (int i = 0; i < s_.models; ++i) {
        Model m;
        m.x << v_n.x(), v_n.y(), math::wrap_pi(spread * i);
        m.p = filters::Vec<3>(s_.velocity_noise_mps * s_.velocity_noise_mps,
                              s_.velocity_noise_mps * s_.velocity_noise_mps, 0.25 * spread * spread)
                  .asDiagonal();
        m.weight = 1.0 / s_.models;
        models_.push_back(m);
    }
}

void YawGsf::predict(double dt, const math::Vec3& w_b, const math::Vec3& f_b, double pitch, double bank) {
    const double yaw_rate = (w_b.y() * std::sin(bank) + w_b.z() * std::cos(bank)) / std::cos(pitch);
    const math::Vec3 lev = math::dcm_from_euler({0.0, pitch, bank}) * f_b;
    const double qa = s_.accel_noise_mps2 * s_.accel_noise_mps2 * dt * dt;
    const double qw = s_.rate_noise_rps * s_.rate_noise_rps * dt * dt;
    accel_sum_mps2_ += std::hypot(lev.x(), lev.y());
    ++accel_count_;
    for (Model& m : models_) {
        const double c = std::cos(m.x(2)), s = std::sin(m.x(2));
        const double a_n = c * lev.x() - s * lev.y();
        const double a_e = s * lev.x() + c * lev.y();
        filters::SqMat<3> f = filters::SqMat<3>::Identity();
        f(0, 2) = -a_e * dt;
        f(1, 2) = a_n * dt;
        m.x(0) += dt * a_n;
        m.x(1) += dt * a_e;
        m.x(2) = math::wrap_pi(m.x(2) + dt * yaw_rate);
        filters::propagate_covariance_diag<3>(m.p, f, filters::Vec<3>(qa, qa, qw));
    }
}

void YawGsf::update(const math::Vec3& v_n) {
    turn_accel_mps2_ = accel_count_ > 0 ? accel_sum_mps2_ / accel_count_ : 0.0;
    accel_sum_mps2_ = 0.0;
    accel_count_ = 0;
    double largest = 0.0;
    const double r = s_.velocity_noise_mps * s_.velocity_noise_mps;
    for (Model& m : models_) {
        filters::Mat<2, 3> h = filters::Mat<2, 3>::Zero();
        h(0, 0) = h(1, 1) = 1.0;
        const filters::Vec<2> innov(v_n.x() - m.x(0), v_n.y() - m.x(1));
        const auto info = filters::joseph_update_diag<3, 2>(m.x, m.p, innov, h, filters::Vec<2>::Constant(r));
        m.x(2) = math::wrap_pi(m.x(2));
        const double det = info.innovation_cov.determinant();
        m.weight *= std::exp(-0.5 * info.nis) / (2.0 * math::kPi * std::sqrt(std::max(det, 1e-30)));
        largest = std::max(largest, m.weight);
    }
    double sum = 0.0;
    for (Model& m : models_) sum += (m.weight = std::max(m.weight, 1e-6 * largest));
    for (Model& m : models_) m.weight = sum > 0.0 ? m.weight / sum : 1.0 / s_.models;
}

double YawGsf::yaw_rad() const {
    double s = 0.0, c = 0.0;
    for (const Model& m : models_) {
        s += m.weight * std::sin(m.x(2));
        c += m.weight * std::cos(m.x(2));
    }
    return std::atan2(s, c);
}

double YawGsf::yaw_variance_rad2() const {
    const double mean = yaw_rad();
    double v = 0.0;
    for (const Model& m : models_) {
        const double d = math::wrap_pi(m.x(2) - mean);
        v += m.weight * (m.p(2, 2) + d * d);
    }
    return v;
}

}  // namespace gdnav::nav
