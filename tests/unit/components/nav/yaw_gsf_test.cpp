// The GNSS-velocity yaw estimator (yaw_gsf.hpp) on synthesised flights: from any true heading (the bank of
// hypotheses is fixed, so the true heading's place among them varies) it converges in a turn, and stays undecided in
// straight flight.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "nav_synthetic.hpp"
#include "yaw_gsf.hpp"

using namespace gdnav;
using namespace gdnav::nav;

namespace {

// Runs the estimator on a synthetic flight with the true tilt (as the attitude filter would give it, to its error)
// plus `tilt_err_rad` on the pitch; returns (heading error, sigma) after `steps`.
std::pair<double, double> run(double yaw0_rad, double bank_deg, int steps, double tilt_err_rad = 0.0) {
    synth::Scenario sc;
    sc.yaw0_rad = yaw0_rad;
    sc.bank_rad = math::deg2rad(bank_deg);
    sc.yaw_rate_rps = 9.80665 * std::tan(sc.bank_rad) / sc.tas_mps;
    synth::Generator gen(sc, rnd::Stream(11));
    YawGsf g{YawGsfSettings{}};
    double yaw_true = 0.0;
    for (int k = 0; k < steps; ++k) {
        const synth::Sample s = gen.next();
        const math::Euler e = math::euler_from_quat(s.truth.q_nb);
        yaw_true = e.yaw_rad;
        if (!g.started()) {
            if (s.gnss.fix_valid) g.start(s.gnss.v_n_mps);
            continue;
        }
        g.predict(sc.dt_s, s.imu.w_b_rps, s.imu.f_b_mps2, e.pitch_rad + tilt_err_rad, e.bank_rad);
        if (s.gnss.fix_valid) g.update(s.gnss.v_n_mps);
    }
    return {math::wrap_pi(g.yaw_rad() - yaw_true), std::sqrt(g.yaw_variance_rad2())};
}

}  // namespace

TEST(NavYawGsf, ConvergesInATurnFromAnyHeading) {
    // 20 deg bank at 30 m/s: 53 s per turn; judged after one and a half turns (8000 steps).
    double worst = 0.0;
    for (int i = 0; i < 12; ++i) {
        const double yaw0 = math::deg2rad(-180.0 + 30.0 * i + 7.0);
        const auto [err, sigma] = run(yaw0, 20.0, 8000);
        std::printf("true initial heading %+6.1f deg: error %+.3f deg, sigma %.3f deg\n", math::rad2deg(yaw0),
                    math::rad2deg(err), math::rad2deg(sigma));
        worst = std::max(worst, std::fabs(err));
        EXPECT_LT(std::fabs(err), 3.0 * sigma + math::deg2rad(0.5));
        EXPECT_LT(sigma, math::deg2rad(3.0));
    }
    EXPECT_LT(math::rad2deg(worst), 3.0);
}

TEST(NavYawGsf, ToleratesATiltErrorInTheTurn) {
    const auto [err, sigma] = run(1.0, 20.0, 8000, math::deg2rad(1.0));
    EXPECT_LT(std::fabs(math::rad2deg(err)), 5.0) << math::rad2deg(sigma);
}

TEST(NavYawGsf, StaysUndecidedInStraightFlight) {
    const auto [err, sigma] = run(1.0, 0.0, 8000);
    std::printf("straight: error %+.2f deg, sigma %.2f deg\n", math::rad2deg(err), math::rad2deg(sigma));
    EXPECT_GT(math::rad2deg(sigma), 20.0);
}

// The turn gate's measure (YawGsf::turn_accel_mps2): in a coordinated turn at bank phi the levelled horizontal
// specific force is the centripetal acceleration g tan(phi); in straight and level flight it is the sensor noise.
TEST(NavYawGsf, MeasuresTheTurnsCentripetalAcceleration) {
    for (const double bank_deg : {0.0, 10.0, 20.0, 30.0}) {
        synth::Scenario sc;
        sc.bank_rad = math::deg2rad(bank_deg);
        sc.yaw_rate_rps = 9.80665 * std::tan(sc.bank_rad) / sc.tas_mps;
        synth::Generator gen(sc, rnd::Stream(5));
        YawGsf g{YawGsfSettings{}};
        EXPECT_EQ(g.turn_accel_mps2(), 0.0);
        for (int k = 0; k < 3000; ++k) {
            const synth::Sample s = gen.next();
            const math::Euler e = math::euler_from_quat(s.truth.q_nb);
            if (!g.started()) {
                if (s.gnss.fix_valid) g.start(s.gnss.v_n_mps);
                continue;
            }
            g.predict(sc.dt_s, s.imu.w_b_rps, s.imu.f_b_mps2, e.pitch_rad, e.bank_rad);
            if (s.gnss.fix_valid) g.update(s.gnss.v_n_mps);
        }
        const double expected = 9.80665 * std::tan(sc.bank_rad);
        std::printf("bank %4.1f deg: turn acceleration %.3f m/s^2 (g tan(bank) %.3f)\n", bank_deg,
                    g.turn_accel_mps2(), expected);
        EXPECT_NEAR(g.turn_accel_mps2(), expected, 0.05 * expected + 0.3);
    }
}
