// The GNSS-velocity yaw estimator (yaw_gsf.hpp) on synthesised flights: from any true heading (the bank of
// hypotheses is fixed, so the true heading's place among them varies) it converges in a turn, and stays undecided in
// straight flight.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>

#include "nav_synthetic.hpp"
#include "yaw_gsf.hpp"

using namespace gdnav;
using namespace gdnav::nav;

namespace {

// The estimator flown `steps` steps on a synthetic coordinated flight at `bank_deg` from heading `yaw0_rad` (stream
// seed `seed`), with the true tilt (as the attitude filter would give it, to its error) plus `tilt_err_rad` on the
// pitch; `yaw_true_rad` is the true heading at the last step.
struct Flown {
    YawGsf gsf{YawGsfSettings{}};
    double yaw_true_rad{0.0};
};
Flown fly(double yaw0_rad, double bank_deg, int steps, std::uint64_t seed, double tilt_err_rad = 0.0) {
    synth::Scenario sc;
    sc.yaw0_rad = yaw0_rad;
    sc.bank_rad = math::deg2rad(bank_deg);
    sc.yaw_rate_rps = 9.80665 * std::tan(sc.bank_rad) / sc.tas_mps;
    synth::Generator gen(sc, rnd::Stream(seed));
    Flown f;
    YawGsf& g = f.gsf;
    for (int k = 0; k < steps; ++k) {
        const synth::Sample s = gen.next();
        const math::Euler e = math::euler_from_quat(s.truth.q_nb);
        f.yaw_true_rad = e.yaw_rad;
        if (!g.started()) {
            if (s.gnss.fix_valid) g.start(s.gnss.v_n_mps);
            continue;
        }
        g.predict(sc.dt_s, s.imu.w_b_rps, s.imu.f_b_mps2, e.pitch_rad + tilt_err_rad, e.bank_rad);
        if (s.gnss.fix_valid) g.update(s.gnss.v_n_mps);
    }
    return f;
}

// (heading error, sigma) after `steps`.
std::pair<double, double> run(double yaw0_rad, double bank_deg, int steps, double tilt_err_rad = 0.0) {
    const Flown f = fly(yaw0_rad, bank_deg, steps, 11, tilt_err_rad);
    return {math::wrap_pi(f.gsf.yaw_rad() - f.yaw_true_rad), std::sqrt(f.gsf.yaw_variance_rad2())};
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
    EXPECT_EQ(YawGsf{YawGsfSettings{}}.turn_accel_mps2(), 0.0);
    for (const double bank_deg : {0.0, 10.0, 20.0, 30.0}) {
        const YawGsf g = fly(synth::Scenario{}.yaw0_rad, bank_deg, 3000, 5).gsf;
        const double expected = 9.80665 * std::tan(math::deg2rad(bank_deg));
        std::printf("bank %4.1f deg: turn acceleration %.3f m/s^2 (g tan(bank) %.3f)\n", bank_deg,
                    g.turn_accel_mps2(), expected);
        EXPECT_NEAR(g.turn_accel_mps2(), expected, 0.05 * expected + 0.3);
    }
}
