#include "flight_physics/model/dryden.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace gdnav::physics {

namespace {
constexpr double kFt_m = 0.3048;
// MIL-F-8785C high-altitude turbulence intensity chart (as tabulated by JSBSim), sigma [ft/s] vs altitude [ft].
constexpr std::array<double, 6> kAltFt{500.0, 1750.0, 3750.0, 7500.0, 15000.0, 25000.0};
constexpr std::array<std::array<double, 6>, 3> kSigmaFtps{{
    {4.2, 3.6, 3.3, 1.6, 0.0, 0.0},    // P = 1e-1
    {6.6, 6.9, 7.4, 6.7, 4.6, 2.7},    // P = 1e-2 ("light")
    {8.6, 9.6, 10.6, 10.1, 8.0, 6.6},  // P = 1e-3 ("moderate")
}};
constexpr double kMinTas_mps = 1.0;

double row_at(const std::array<double, 6>& row, double alt_ft) {
    if (alt_ft <= kAltFt.front()) return row.front();
    if (alt_ft >= kAltFt.back()) return row.back();
    std::size_t i = 0;
    while (alt_ft > kAltFt[i + 1]) ++i;
    const double t = (alt_ft - kAltFt[i]) / (kAltFt[i + 1] - kAltFt[i]);
    return row[i] + t * (row[i + 1] - row[i]);
}

// Stationary covariance of x+ = phi x + gamma nu (unit nu): P = phi P phi^T + gamma gamma^T, via vec().
Eigen::Matrix2d lyapunov(const Eigen::Matrix2d& phi, const Eigen::Vector2d& gamma) {
    Eigen::Matrix4d m;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k)
                for (int l = 0; l < 2; ++l) m(2 * i + j, 2 * k + l) = phi(i, k) * phi(j, l);
    const Eigen::Matrix2d q = gamma * gamma.transpose();
    const Eigen::Vector4d rhs(q(0, 0), q(0, 1), q(1, 0), q(1, 1));
    const Eigen::Vector4d v = (Eigen::Matrix4d::Identity() - m).partialPivLu().solve(rhs);
    Eigen::Matrix2d p;
    p << v(0), 0.5 * (v(1) + v(2)), 0.5 * (v(1) + v(2)), v(3);
    return p;
}
}  // namespace

TurbulenceParams TurbulenceParams::from_config(const config::Config& c) {
    TurbulenceParams p;
    p.factor = c.get_double("factor", p.factor, config::Range{0.0, 10.0});
    p.prob_exceedance = c.get_double("probability_of_exceedance", p.prob_exceedance, config::Range{1e-3, 1e-1});
    p.scale_length_m = c.get_double("scale_length_m", p.scale_length_m, config::Range{1.0, 1e5});
    return p;
}

DrydenTurbulence::DrydenTurbulence(const TurbulenceParams& p, rnd::Stream stream) : p_(p), stream_(stream) {
    if (!(p.factor >= 0.0)) throw std::invalid_argument("DrydenTurbulence: factor must be >= 0");
    if (!(p.prob_exceedance >= 1e-3 && p.prob_exceedance <= 1e-1))
        throw std::invalid_argument("DrydenTurbulence: probability of exceedance must be in [1e-3, 1e-1]");
    if (!(p.scale_length_m > 0.0)) throw std::invalid_argument("DrydenTurbulence: scale length must be > 0");
}

double DrydenTurbulence::sigma_mps(double h_m, double prob) {
    const double alt_ft = h_m / kFt_m;
    const double e = std::clamp(-std::log10(prob), 1.0, 3.0);  // 1 .. 3 -> rows 0 .. 2
    const auto i = std::min<std::size_t>(static_cast<std::size_t>(e - 1.0), 1);
    const double t = e - 1.0 - static_cast<double>(i);
    const double s = (1.0 - t) * row_at(kSigmaFtps[i], alt_ft) + t * row_at(kSigmaFtps[i + 1], alt_ft);
    return s * kFt_m;
}

void DrydenTurbulence::set_conditions(double tas_mps, double h_m, double dt_s) {
    if (!active()) return;
    const double v = std::max(tas_mps, kMinTas_mps);
    const double a = v / p_.scale_length_m;  // 1 / time constant
    const double x = a * dt_s;
    const double e = std::exp(-x);
    sigma_ = p_.factor * sigma_mps(h_m, p_.prob_exceedance);
    // u: first order.
    a_u_ = e;
    g_u_ = sigma_ * std::sqrt(-std::expm1(-2.0 * x));
    // v, w: (1 + sqrt3 s/a) / (1 + s/a)^2 = (a^2 + sqrt3 a s) / (s + a)^2;
    // xdot = A x + B nu, A = [0 1; -a^2 -2a], B = (0, 1), y = (a^2, sqrt3 a) x.
    // exp(A t) = e^-at (I + t (A + a I)); gamma = int_0^dt exp(A tau) B dtau = (I1, I0 - a I1).
    Mat2 apa;
    apa << a, 1.0, -a * a, -a;
    phi_ = e * (Mat2::Identity() + dt_s * apa);
    const double i0 = -std::expm1(-x) / a;
    const double i1 = (-std::expm1(-x) - x * e) / (a * a);
    const Vec2 gamma_unit(i1, i0 - a * i1);
    c_ = Vec2(a * a, std::sqrt(3.0) * a);
    const Mat2 p1 = lyapunov(phi_, gamma_unit);
    const double var1 = c_.dot(p1 * c_);
    const double g = sigma_ / std::sqrt(var1);
    gamma_ = g * gamma_unit;
    p_vw_ = (g * g) * p1;
}

void DrydenTurbulence::reset_stationary() {
    if (!active()) return;
    x_u_ = sigma_ * stream_.normal();
    const Eigen::LLT<Mat2> llt(p_vw_);
    const Mat2 l = llt.matrixL();
    x_v_ = l * Vec2(stream_.normal(), stream_.normal());
    x_w_ = l * Vec2(stream_.normal(), stream_.normal());
    out_ = math::Vec3(x_u_, c_.dot(x_v_), c_.dot(x_w_));
}

const math::Vec3& DrydenTurbulence::step() {
    if (!active()) return out_;
    const double nu = stream_.normal();
    const double nv = stream_.normal();
    const double nw = stream_.normal();
    x_u_ = a_u_ * x_u_ + g_u_ * nu;
    x_v_ = phi_ * x_v_ + gamma_ * nv;
    x_w_ = phi_ * x_w_ + gamma_ * nw;
    out_ = math::Vec3(x_u_, c_.dot(x_v_), c_.dot(x_w_));
    return out_;
}

}  // namespace gdnav::physics
