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
constexpr double kMaxNoiseTau_s = 5.0;

double row_at(const std::array<double, 6>& row, double alt_ft) {
    if (alt_ft <= kAltFt.front()) return row.front();
    if (alt_ft >= kAltFt.back()) return row.back();
    std::size_t i = 0;
    while (alt_ft > kAltFt[i + 1]) ++i;
    const double t = (alt_ft - kAltFt[i]) / (kAltFt[i + 1] - kAltFt[i]);
    return row[i] + t * (row[i + 1] - row[i]);
}

// Stationary covariance of z+ = phi z + gamma nu (unit nu): P = phi P phi' + gamma gamma', solved through vec().
template <int N>
Eigen::Matrix<double, N, N> lyapunov(const TurbulenceAxisModel<N>& m) {
    constexpr int kN2 = N * N;
    Eigen::Matrix<double, kN2, kN2> k;
    for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j)
            for (int r = 0; r < N; ++r)
                for (int l = 0; l < N; ++l) k(N * i + j, N * r + l) = m.phi(i, r) * m.phi(j, l);
    const Eigen::Matrix<double, N, N> q = m.gamma * m.gamma.transpose();
    const Eigen::Matrix<double, kN2, 1> rhs = Eigen::Map<const Eigen::Matrix<double, kN2, 1>>(q.data());
    const Eigen::Matrix<double, kN2, 1> v = (Eigen::Matrix<double, kN2, kN2>::Identity() - k).partialPivLu().solve(rhs);
    const Eigen::Matrix<double, N, N> p = Eigen::Map<const Eigen::Matrix<double, N, N>>(v.data());
    return 0.5 * (p + p.transpose());
}

// Stationary draw of z ~ N(0, P).
template <int N>
Eigen::Matrix<double, N, 1> draw_stationary(const TurbulenceAxisModel<N>& m, rnd::Stream& stream) {
    const Eigen::LLT<Eigen::Matrix<double, N, N>> llt(lyapunov(m));
    Eigen::Matrix<double, N, 1> nu;
    for (int i = 0; i < N; ++i) nu(i) = stream.normal();
    return llt.matrixL() * nu;
}
}  // namespace

double reference_intensity_mps() {
    return DrydenTurbulence::intensity_for(kReferenceUdotRms_mps2, kDefaultNoiseTimeConstant_s, kReferenceTas_mps,
                                           kDefaultScaleLength_m);
}

TurbulenceParams TurbulenceParams::from_config(const config::Config& c) {
    TurbulenceParams p;
    p.factor = c.get_double("factor", p.factor, config::Range{0.0, 10.0});
    if (c.has("intensity_mps") && c.has("probability_of_exceedance"))
        c.fail("probability_of_exceedance",
               "give either intensity_mps (constant intensity) or probability_of_exceedance (MIL-F-8785C chart), "
               "not both");
    p.intensity_mps = c.get_double("intensity_mps", p.intensity_mps, config::Range{0.0, 10.0});
    if (c.has("probability_of_exceedance"))
        p.prob_exceedance = c.get_double("probability_of_exceedance", 1e-2, config::Range{1e-3, 1e-1});
    p.scale_length_m = c.get_double("scale_length_m", p.scale_length_m, config::Range{1.0, 1e5});
    p.noise_time_constant_s =
        c.get_double("noise_time_constant_s", p.noise_time_constant_s, config::Range{0.0, kMaxNoiseTau_s});
    return p;
}

DrydenTurbulence::DrydenTurbulence(const TurbulenceParams& p, rnd::Stream stream) : p_(p), stream_(stream) {
    if (!(p.factor >= 0.0)) throw std::invalid_argument("DrydenTurbulence: factor must be >= 0");
    if (!(p.intensity_mps >= 0.0)) throw std::invalid_argument("DrydenTurbulence: intensity must be >= 0");
    if (p.prob_exceedance && !(*p.prob_exceedance >= 1e-3 && *p.prob_exceedance <= 1e-1))
        throw std::invalid_argument("DrydenTurbulence: probability of exceedance must be in [1e-3, 1e-1]");
    if (!(p.scale_length_m > 0.0)) throw std::invalid_argument("DrydenTurbulence: scale length must be > 0");
    if (!(p.noise_time_constant_s >= 0.0 && p.noise_time_constant_s <= kMaxNoiseTau_s))
        throw std::invalid_argument("DrydenTurbulence: noise time constant must be in [0, 5] s");
}

double DrydenTurbulence::sigma_mps(double h_m, double prob) {
    const double alt_ft = h_m / kFt_m;
    const double e = std::clamp(-std::log10(prob), 1.0, 3.0);  // 1 .. 3 -> rows 0 .. 2
    const auto i = std::min<std::size_t>(static_cast<std::size_t>(e - 1.0), 1);
    const double t = e - 1.0 - static_cast<double>(i);
    const double s = (1.0 - t) * row_at(kSigmaFtps[i], alt_ft) + t * row_at(kSigmaFtps[i + 1], alt_ft);
    return s * kFt_m;
}

double DrydenTurbulence::noise_time_constant_for(double udot_rms_mps2, double sigma_mps, double tas_mps,
                                                 double scale_length_m) {
    if (!(udot_rms_mps2 > 0.0 && sigma_mps > 0.0 && tas_mps > 0.0 && scale_length_m > 0.0))
        throw std::invalid_argument("DrydenTurbulence::noise_time_constant_for: arguments must be > 0");
    // sigma^2 / (tau (T + tau)) = udot^2  <=>  tau^2 + T tau - c = 0, c = sigma^2 / udot^2; root in the form
    // 2c / (T + sqrt(T^2 + 4c)) to avoid cancellation when c << T^2.
    const double t = scale_length_m / tas_mps;
    const double c = (sigma_mps / udot_rms_mps2) * (sigma_mps / udot_rms_mps2);
    return 2.0 * c / (t + std::sqrt(t * t + 4.0 * c));
}

double DrydenTurbulence::intensity_for(double udot_rms_mps2, double tau_s, double tas_mps, double scale_length_m) {
    if (!(udot_rms_mps2 > 0.0 && tau_s > 0.0 && tas_mps > 0.0 && scale_length_m > 0.0))
        throw std::invalid_argument("DrydenTurbulence::intensity_for: arguments must be > 0");
    return udot_rms_mps2 * std::sqrt(tau_s * (scale_length_m / tas_mps + tau_s));
}

void DrydenTurbulence::set_conditions(double tas_mps, double h_m, double dt_s) {
    if (!active()) return;
    const double v = std::max(tas_mps, kMinTas_mps);
    const double a = v / p_.scale_length_m;  // 1 / T
    const double x = a * dt_s;
    const double e = std::exp(-x);
    sigma_ = p_.factor * (p_.prob_exceedance ? sigma_mps(h_m, *p_.prob_exceedance) : p_.intensity_mps);
    // Noise: f+ = b f + sqrt(1 - b^2) nu; zero-frequency PSD of the sampled f: q = dt (1 + b) / (1 - b) (= dt for
    // white f, ~2 tau for tau >> dt). The forming-filter gains below use it so that the discrete model's
    // low-frequency spectrum is the continuous Dryden one.
    const double tau = p_.noise_time_constant_s;
    b_ = tau > 0.0 ? std::exp(-dt_s / tau) : 0.0;
    s_ = tau > 0.0 ? std::sqrt(-std::expm1(-2.0 * dt_s / tau)) : 1.0;
    const double q = tau > 0.0 ? dt_s * (1.0 + b_) / -std::expm1(-dt_s / tau) : dt_s;
    const double t = 1.0 / a;
    // u: T xdot = -x + K_u f, K_u = sigma sqrt(2T / q); ZOH: x+ = e x + (1 - e) K_u f.
    a_u_ = e;
    g_u_ = -std::expm1(-x) * sigma_ * std::sqrt(2.0 * t / q);
    // v, w: (1 + sqrt3 s/a) / (1 + s/a)^2 = (a^2 + sqrt3 a s) / (s + a)^2;
    // xdot = A x + B f, A = [0 1; -a^2 -2a], B = (0, K_v), y = (a^2, sqrt3 a) x, K_v = sigma sqrt(T / q).
    // exp(A t) = e^-at (I + t (A + a I)); gamma = K_v int_0^dt exp(A tau) (0, 1) dtau = K_v (I1, I0 - a I1).
    Mat2 apa;
    apa << a, 1.0, -a * a, -a;
    phi_ = e * (Mat2::Identity() + dt_s * apa);
    const double i0 = -std::expm1(-x) / a;
    const double i1 = (-std::expm1(-x) - x * e) / (a * a);
    gamma_ = sigma_ * std::sqrt(t / q) * Vec2(i1, i0 - a * i1);
    c_ = Vec2(a * a, std::sqrt(3.0) * a);
}

TurbulenceAxisModel<2> DrydenTurbulence::u_model() const {
    TurbulenceAxisModel<2> m;
    m.phi << b_, 0.0, g_u_, a_u_;
    m.gamma << s_, 0.0;
    m.c << 0.0, 1.0;
    return m;
}

TurbulenceAxisModel<3> DrydenTurbulence::vw_model() const {
    TurbulenceAxisModel<3> m;
    m.phi.setZero();
    m.phi(0, 0) = b_;
    m.phi.block<2, 1>(1, 0) = gamma_;
    m.phi.block<2, 2>(1, 1) = phi_;
    m.gamma << s_, 0.0, 0.0;
    m.c << 0.0, c_(0), c_(1);
    return m;
}

void DrydenTurbulence::reset_stationary() {
    if (!active()) return;
    const Eigen::Vector2d zu = draw_stationary(u_model(), stream_);
    const TurbulenceAxisModel<3> mvw = vw_model();
    const Eigen::Vector3d zv = draw_stationary(mvw, stream_);
    const Eigen::Vector3d zw = draw_stationary(mvw, stream_);
    f_ = math::Vec3(zu(0), zv(0), zw(0));
    x_u_ = zu(1);
    x_v_ = zv.tail<2>();
    x_w_ = zw.tail<2>();
    out_ = math::Vec3(x_u_, c_.dot(x_v_), c_.dot(x_w_));
}

const math::Vec3& DrydenTurbulence::step() {
    if (!active()) return out_;
    // Forming filters with the noise held over the step, then the noise low-pass.
    x_u_ = a_u_ * x_u_ + g_u_ * f_(0);
    x_v_ = phi_ * x_v_ + gamma_ * f_(1);
    x_w_ = phi_ * x_w_ + gamma_ * f_(2);
    const double nu = stream_.normal();
    const double nv = stream_.normal();
    const double nw = stream_.normal();
    f_ = b_ * f_ + s_ * math::Vec3(nu, nv, nw);
    out_ = math::Vec3(x_u_, c_.dot(x_v_), c_.dot(x_w_));
    return out_;
}

}  // namespace gdnav::physics
