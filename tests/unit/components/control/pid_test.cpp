// Discrete PID and set-point ramp against hand-computed sequences (docs/guidance-control.md, "Control").
#include <gtest/gtest.h>

#include <cmath>

#include "control/model/pid.hpp"

using gdnav::control::DiscretePid;
using gdnav::control::PidGains;
using gdnav::control::RampFilter;

namespace {
// T_f = 0.32 s, dt = 0.02 s: the error filter is ef_k = (16 ef_{k-1} + e_k) / 17.
constexpr double kTf = 0.32;
constexpr double kDt = 0.02;
}  // namespace

TEST(DiscretePid, HandComputedSequence) {
    const PidGains g{2.0, 0.5, 3.0, 0.1, -100.0, 100.0};
    DiscretePid pid(g, kTf, kDt);
    // e = 1: I = 1, ef = 1/17, D = 1/17.
    EXPECT_NEAR(pid.step(1.0), 0.1 + 2.0 + 0.5 + 3.0 / 17.0, 1e-14);
    // e = 1: I = 2, ef = (16/17 + 1)/17 = 33/289, D = 33/289 - 17/289 = 16/289.
    EXPECT_NEAR(pid.step(1.0), 0.1 + 2.0 + 1.0 + 3.0 * 16.0 / 289.0, 1e-14);
    EXPECT_NEAR(pid.filtered_error(), 33.0 / 289.0, 1e-15);
    // e = -2: I = 0, ef = (16 * 33/289 - 2)/17 = -50/4913, D = -50/4913 - 33/289 = -611/4913.
    EXPECT_NEAR(pid.step(-2.0), 0.1 - 4.0 + 0.0 + 3.0 * (-611.0 / 4913.0), 1e-14);
    EXPECT_NEAR(pid.integral(), 0.0, 1e-15);
    // e = 0: I = 0, ef = 16/17 * (-50/4913) = -800/83521, D = -800/83521 + 850/83521 = 50/83521.
    EXPECT_NEAR(pid.step(0.0), 0.1 + 3.0 * 50.0 / 83521.0, 1e-14);
    EXPECT_NEAR(pid.derivative(), 50.0 / 83521.0, 1e-16);
}

TEST(DiscretePid, ClampsOutputButNotIntegral) {
    DiscretePid pid(PidGains{1.0, 0.1, 0.0, 0.0, -1.0, 1.0}, kTf, kDt);
    EXPECT_EQ(pid.step(10.0), 1.0);
    EXPECT_EQ(pid.step(10.0), 1.0);
    EXPECT_EQ(pid.step(10.0), 1.0);
    EXPECT_DOUBLE_EQ(pid.integral(), 30.0);  // no anti-windup, as in the reference
    // Unsaturated value: 0 + 1 * (-5) + 0.1 * 25 = -2.5, clamped to -1.
    EXPECT_DOUBLE_EQ(pid.step_unsaturated(-5.0), -2.5);
    EXPECT_EQ(pid.saturate(-2.5), -1.0);
}

TEST(DiscretePid, ResetRestartsFromZeroState) {
    const PidGains g{0.7, 0.2, 5.0, 0.0, -50.0, 50.0};
    DiscretePid pid(g, kTf, kDt);
    for (double e : {3.0, -1.0, 4.0}) pid.step(e);
    pid.reset();
    // First step after a reset: I = e, D = e / 17.
    EXPECT_NEAR(pid.step(2.0), 0.7 * 2.0 + 0.2 * 2.0 + 5.0 * 2.0 / 17.0, 1e-14);
}

TEST(RampFilter, FirstStepsAndPassThrough) {
    RampFilter r;
    r.reset(28.0);
    r.set_steps(8.0);
    EXPECT_NEAR(r.step(30.0), (8.0 * 28.0 + 30.0) / 9.0, 1e-14);
    EXPECT_NEAR(r.step(30.0), 30.0 - 2.0 * (8.0 / 9.0) * (8.0 / 9.0), 1e-13);
    r.set_steps(0.0);
    EXPECT_EQ(r.step(12.5), 12.5);
}

// A unit step reaches 1 - 1/e after k steps with (N/(N+1))^k <= 1/e, i.e. k = ceil(1 / ln(1 + 1/N)):
// N = 8 -> 9 steps (0.18 s at 50 Hz), N = 32 -> 33 (0.66 s), N = 64 -> 65 (1.3 s): about N dt, as
// docs/guidance-control.md ("Control") says.
TEST(RampFilter, TimeConstantIsAboutNSteps) {
    for (const auto& [n, k63] : {std::pair{8.0, 9}, std::pair{16.0, 17}, std::pair{32.0, 33}, std::pair{64.0, 65}}) {
        RampFilter r;
        r.reset(0.0);
        r.set_steps(n);
        const double threshold = 1.0 - std::exp(-1.0);
        for (int k = 1; k <= k63; ++k) {
            const double y = r.step(1.0);
            if (k < k63) {
                EXPECT_LT(y, threshold) << "N = " << n << " k = " << k;
            } else {
                EXPECT_GE(y, threshold) << "N = " << n;
            }
        }
    }
}
