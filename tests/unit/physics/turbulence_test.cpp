// Dryden turbulence: intensity chart, discretisation against the analytic Dryden statistics, long-run statistics.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "flight_physics/model/dryden.hpp"

using namespace gdnav;
using physics::DrydenTurbulence;
using physics::TurbulenceParams;

namespace {
constexpr double kL = 533.4;
double r_u(double x) { return std::exp(-x); }  // normalised Dryden autocorrelations, x = V tau / L
double r_vw(double x) { return std::exp(-x) * (1.0 - 0.5 * x); }
}  // namespace

TEST(Turbulence, IntensityFollowsTheMilF8785cChart) {
    // Chart points (ft/s): P = 1e-2 at 500 ft 6.6; P = 1e-3 at 3750 ft 10.6; P = 1e-1 at 7500 ft 1.6.
    EXPECT_NEAR(DrydenTurbulence::sigma_mps(500.0 * 0.3048, 1e-2), 6.6 * 0.3048, 1e-12);
    EXPECT_NEAR(DrydenTurbulence::sigma_mps(3750.0 * 0.3048, 1e-3), 10.6 * 0.3048, 1e-12);
    EXPECT_NEAR(DrydenTurbulence::sigma_mps(7500.0 * 0.3048, 1e-1), 1.6 * 0.3048, 1e-12);
    // 2700 m = 8858.27 ft, linear between 7500 ft (6.7) and 15000 ft (4.6): 6.3197 ft/s = 1.92625 m/s.
    EXPECT_NEAR(DrydenTurbulence::sigma_mps(2700.0, 1e-2), 1.92625, 1e-4);
    // Halfway in log10(P) between the 1e-2 and 1e-3 curves at 1750 ft: (6.9 + 9.6) / 2 ft/s.
    EXPECT_NEAR(DrydenTurbulence::sigma_mps(1750.0 * 0.3048, std::pow(10.0, -2.5)), 8.25 * 0.3048, 1e-9);
}

TEST(Turbulence, DiscreteModelReproducesDrydenCovariances) {
    TurbulenceParams p;  // factor 0.5, P = 1e-2, L = 533.4 m
    DrydenTurbulence t(p, rnd::Stream(1));
    for (double v : {24.0, 29.0, 34.0}) {
        const double dt = 0.002;
        t.set_conditions(v, 2700.0, dt);
        const double sigma = 0.5 * DrydenTurbulence::sigma_mps(2700.0, 1e-2);
        EXPECT_NEAR(t.sigma_out_mps(), sigma, 1e-15);
        // u: pole exp(-V dt / L) and stationary variance g^2 / (1 - a^2) = sigma^2.
        EXPECT_NEAR(t.u_pole(), std::exp(-v * dt / kL), 1e-15);
        EXPECT_NEAR(t.u_gain() * t.u_gain() / (1.0 - t.u_pole() * t.u_pole()), sigma * sigma, 1e-9 * sigma * sigma);
        // v, w: stationary covariance by plain iteration of P = phi P phi' + gamma gamma' (independent of the
        // Lyapunov solve), then the lagged covariances c' phi^k P c against the analytic Dryden ones.
        const auto& phi = t.vw_phi();
        const auto& gam = t.vw_gamma();
        const auto& c = t.vw_c();
        Eigen::Matrix2d pk = Eigen::Matrix2d::Zero();
        const Eigen::Matrix2d q = gam * gam.transpose();
        // Doubling: after n rounds P = sum_{k < 2^n} phi^k q phi'^k.
        Eigen::Matrix2d a = phi;
        pk = q;
        for (int i = 0; i < 40; ++i) {
            pk = pk + a * pk * a.transpose();
            a = a * a;
        }
        EXPECT_NEAR(c.dot(pk * c), sigma * sigma, 1e-6 * sigma * sigma) << v;
        for (double x : {0.25, 0.5, 1.0, 2.0}) {
            const int k = static_cast<int>(std::lround(x * kL / (v * dt)));
            Eigen::Matrix2d phik = Eigen::Matrix2d::Identity();
            Eigen::Matrix2d base = phi;
            for (int e = k; e > 0; e >>= 1) {
                if (e & 1) phik = phik * base;
                base = base * base;
            }
            const double xk = k * v * dt / kL;
            EXPECT_NEAR(c.dot(phik * pk * c) / (sigma * sigma), r_vw(xk), 2e-4) << "V " << v << " x " << x;
            EXPECT_NEAR(std::pow(t.u_pole(), k), r_u(xk), 1e-12);
        }
    }
}

TEST(Turbulence, LongRunStatisticsMatchDryden) {
    // 100 independent 2000-s records at 500 Hz (2e5 s in total, about 10^4 correlation times L / V).
    const double v = 29.0, h = 2700.0, dt = 0.002;
    const double sigma = 0.5 * DrydenTurbulence::sigma_mps(h, 1e-2);
    const int lag_full = static_cast<int>(std::lround(kL / v / dt));  // tau = L / V
    const int lag_half = lag_full / 2;                                // tau = L / (2 V)
    const int lag_quarter = lag_full / 4;
    const int steps = static_cast<int>(2000.0 / dt);
    Eigen::Vector3d s0 = Eigen::Vector3d::Zero(), s2 = Eigen::Vector3d::Zero();
    Eigen::Vector3d c_full = Eigen::Vector3d::Zero(), c_half = Eigen::Vector3d::Zero();
    Eigen::Vector3d c_quarter = Eigen::Vector3d::Zero();
    long n = 0, n_full = 0, n_half = 0, n_quarter = 0;
    std::vector<Eigen::Vector3d> ring(static_cast<std::size_t>(lag_full) + 1);
    rnd::Stream master = rnd::Stream::derive(2024, 0, "flight_physics/turbulence");
    for (int rec = 0; rec < 100; ++rec) {
        DrydenTurbulence t(TurbulenceParams{}, master.child("record" + std::to_string(rec)));
        t.set_conditions(v, h, dt);
        t.reset_stationary();
        for (int k = 0; k < steps; ++k) {
            const Eigen::Vector3d y = t.step();
            const std::size_t slot = static_cast<std::size_t>(k) % ring.size();
            ring[slot] = y;
            s0 += y;
            s2 += y.cwiseProduct(y);
            ++n;
            auto lagged = [&](int lag) { return ring[(static_cast<std::size_t>(k - lag)) % ring.size()]; };
            if (k >= lag_full) {
                c_full += y.cwiseProduct(lagged(lag_full));
                ++n_full;
            }
            if (k >= lag_half) {
                c_half += y.cwiseProduct(lagged(lag_half));
                ++n_half;
            }
            if (k >= lag_quarter) {
                c_quarter += y.cwiseProduct(lagged(lag_quarter));
                ++n_quarter;
            }
        }
    }
    const Eigen::Vector3d var = s2 / static_cast<double>(n);
    const double x_full = lag_full * v * dt / kL, x_half = lag_half * v * dt / kL, x_q = lag_quarter * v * dt / kL;
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(s0(i) / static_cast<double>(n), 0.0, 0.05 * sigma) << "axis " << i;
        EXPECT_NEAR(std::sqrt(var(i)), sigma, 0.10 * sigma) << "axis " << i;
        const double rho_half = c_half(i) / static_cast<double>(n_half) / var(i);
        const double rho_q = c_quarter(i) / static_cast<double>(n_quarter) / var(i);
        const double ref_half = i == 0 ? r_u(x_half) : r_vw(x_half);
        const double ref_q = i == 0 ? r_u(x_q) : r_vw(x_q);
        EXPECT_NEAR(rho_half, ref_half, 0.10 * ref_half) << "axis " << i;
        EXPECT_NEAR(rho_q, ref_q, 0.10 * ref_q) << "axis " << i;
        RecordProperty("rho_axis" + std::to_string(i),
                       "L/2V: " + std::to_string(rho_half) + " (ref " + std::to_string(ref_half) +
                           ") L/4V: " + std::to_string(rho_q) + " (ref " + std::to_string(ref_q) + ")");
    }
    const double rho_u_full = c_full(0) / static_cast<double>(n_full) / var(0);
    EXPECT_NEAR(rho_u_full, r_u(x_full), 0.10 * r_u(x_full));
    RecordProperty("rho_u_L_over_V", std::to_string(rho_u_full) + " (ref " + std::to_string(r_u(x_full)) + ")");
    RecordProperty("sigma_expected_mps", std::to_string(sigma));
    RecordProperty("sigma_u_v_w_mps", std::to_string(std::sqrt(var(0))) + " " + std::to_string(std::sqrt(var(1))) +
                                          " " + std::to_string(std::sqrt(var(2))));
}

TEST(Turbulence, FactorZeroIsSilentAndBadParamsThrow) {
    TurbulenceParams p;
    p.factor = 0.0;
    DrydenTurbulence t(p, rnd::Stream(3));
    t.set_conditions(29.0, 2700.0, 0.002);
    t.reset_stationary();
    for (int i = 0; i < 100; ++i) EXPECT_EQ(t.step().norm(), 0.0);
    p.factor = 0.5;
    p.prob_exceedance = 0.5;
    EXPECT_THROW(DrydenTurbulence(p, rnd::Stream(3)), std::invalid_argument);
}

TEST(Turbulence, SameStreamSameRealisation) {
    DrydenTurbulence a(TurbulenceParams{}, rnd::Stream(9)), b(TurbulenceParams{}, rnd::Stream(9));
    for (auto* t : {&a, &b}) {
        t->set_conditions(29.0, 2700.0, 0.002);
        t->reset_stationary();
    }
    for (int i = 0; i < 1000; ++i) EXPECT_EQ(a.step(), b.step());
}

TEST(Turbulence, ParamsFromConfig) {
    const auto c = config::Config::parse("factor: 1.0\nprobability_of_exceedance: 0.001\n", "turb.yaml");
    const TurbulenceParams p = TurbulenceParams::from_config(c);
    c.finish();
    EXPECT_EQ(p.factor, 1.0);
    EXPECT_EQ(p.prob_exceedance, 1e-3);
    EXPECT_EQ(p.scale_length_m, 533.4);
    const auto bad = config::Config::parse("probability_of_exceedance: 0.5\n", "turb.yaml");
    EXPECT_THROW(TurbulenceParams::from_config(bad), config::ConfigError);
}
