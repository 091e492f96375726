// Position filter: GNSS-aided wind and pressure-offset estimation, GNSS-loss logic (simulated time), and the
// GNSS-denied baseline reconstruction on synthetic constant-wind flight.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "nav_chain.hpp"

using namespace gdnav;
using namespace gdnav::nav;

TEST(NavGnssLoss, SwitchesExactlyAfterTimeoutWithoutFix) {
    GnssLossMonitor m(1.5);
    m.reset(-50.0);
    const double dt = 0.01;
    // Last fix at t = 100 s (k = 15000 with t0 = -50 s), then nothing.
    for (int k = 0; k <= 15000; ++k) EXPECT_FALSE(m.update(-50.0 + k * dt, k % 100 == 0));
    for (int k = 15001; k <= 15150; ++k) {
        EXPECT_FALSE(m.update(-50.0 + k * dt, false)) << k;  // up to and including t = 101.5 s
        EXPECT_FALSE(m.denied());
    }
    EXPECT_TRUE(m.update(-50.0 + 15151 * dt, false));  // 1.51 s without a fix: switch, reported once
    EXPECT_TRUE(m.denied());
    EXPECT_FALSE(m.update(-50.0 + 15152 * dt, true));  // one-way: later fixes are ignored
    EXPECT_TRUE(m.denied());
}

TEST(NavGnssLoss, PublisherDeadSwitchesImmediatelyEvenWithAFix) {
    GnssLossMonitor m(1.5);
    m.reset(0.0);
    EXPECT_FALSE(m.update(0.01, false));
    m.set_publisher_dead();
    EXPECT_TRUE(m.update(0.02, true));
    EXPECT_TRUE(m.denied());
}

TEST(NavPosition, EstimatesWindAndPressureOffsetWithGnss) {
    // Straight flight, constant wind (3, -4, 0) m/s, dT = 5 K, dp = 300 Pa; 150 s GNSS-aided (as the paper's runs).
    synth::Scenario sc;
    test::ChainOptions o;
    o.steps = 15000;
    const test::ChainRun r = test::run_chain(sc, o, 51);
    const PositionEstimate& p = r.pos.back();
    // Error sources: attitude (~0.05 deg x 30 m/s = 0.03 m/s), GNSS velocity noise 0.074 m/s low-passed over 3 s,
    // airspeed noise 0.33 m/s filtered by the air data filter; tolerance 0.15 m/s per axis.
    EXPECT_NEAR(p.wind_n_mps.x(), sc.wind_n_mps.x(), 0.15);
    EXPECT_NEAR(p.wind_n_mps.y(), sc.wind_n_mps.y(), 0.15);
    EXPECT_NEAR(p.wind_n_mps.z(), sc.wind_n_mps.z(), 0.15);
    // dp: 1 m of altitude is ~12 Pa at 3 km; the filtered GNSS altitude is good to ~1 m, the barometer noise is
    // 100 Pa per sample, low-passed over 3 s (~300 samples): tolerance 25 Pa.
    EXPECT_NEAR(p.dp_Pa, sc.dp_Pa, 25.0);
    EXPECT_NEAR(p.dT_K, sc.dT_K, 0.05);
    EXPECT_LT(test::hor_error_m(r, r.pos.size() - 1), 3.0);
    EXPECT_NEAR(p.h_m, r.data.back().truth.h_m, 2.0);
    EXPECT_FALSE(p.gnss_denied);
}

TEST(NavPosition, EntersDeniedModeExactly1p5sAfterTheLastFix) {
    synth::Scenario sc;
    test::ChainOptions o;
    o.steps = 10300;
    o.last_fix_step = 10000;  // t = 100 s
    const test::ChainRun r = test::run_chain(sc, o, 52);
    for (int k = 0; k <= 10150; ++k) ASSERT_FALSE(r.pos[k].gnss_denied) << k;
    EXPECT_TRUE(r.pos[10151].gnss_denied);
    EXPECT_TRUE(r.pos[10151].gnss_lost_event);
    int events = 0;
    for (const auto& p : r.pos) events += p.gnss_lost_event ? 1 : 0;
    EXPECT_EQ(events, 1);
    // Wind and dp are frozen at their values of the last fix (step 10000).
    EXPECT_EQ(r.pos[10151].wind_n_mps, r.pos[10000].wind_n_mps);
    EXPECT_EQ(r.pos[10300].dp_Pa, r.pos[10000].dp_Pa);
}

TEST(NavPosition, PublisherDeadSwitchesOnTheNextStep) {
    synth::Scenario sc;
    test::ChainOptions o;
    o.steps = 600;
    o.dead_at_step = 500;  // a fix arrives at step 500 too: it must be ignored
    const test::ChainRun r = test::run_chain(sc, o, 53);
    EXPECT_FALSE(r.pos[499].gnss_denied);
    EXPECT_TRUE(r.pos[500].gnss_denied);
    EXPECT_TRUE(r.pos[500].gnss_lost_event);
    EXPECT_EQ(r.pos[500].wind_n_mps, r.pos[400].wind_n_mps);  // frozen at the last fix used (step 400)
}

TEST(NavPosition, DeniedBaselineWithConstantWindDriftsSlowly) {
    // Constant wind and atmosphere: after the loss the only velocity errors are the wind estimate at the loss,
    // attitude and filtered airspeed errors (~0.1-0.2 m/s), so 200 s of GNSS-denied flight drift well under 100 m,
    // and the pressure-based altitude keeps the error of dp at the loss (~2 m).
    synth::Scenario sc;
    sc.yaw_rate_rps = 0.01;
    sc.bank_rad = std::atan(0.01 * 30.0 / 9.8);
    test::ChainOptions o;
    o.steps = 35000;
    o.last_fix_step = 15000;
    const test::ChainRun r = test::run_chain(sc, o, 54);
    const std::size_t last = r.pos.size() - 1;
    EXPECT_TRUE(r.pos[last].gnss_denied);
    EXPECT_LT(test::hor_error_m(r, last), 60.0);
    EXPECT_NEAR(r.pos[last].h_m, r.data[last].truth.h_m, 4.0);
    EXPECT_LT((r.pos[last].v_n_mps - r.data[last].truth.v_n_mps).norm(), 0.3);
    // The denied velocity obeys v = wind + R(q) v_tas exactly (same-step air data and attitude estimates).
    const Eigen::Vector3d vtas_n =
        r.att[last].q_nb * math::vtas_body(r.air[last].tas_mps, r.air[last].aoa_rad, r.air[last].aos_rad);
    EXPECT_LT((r.pos[last].v_n_mps - r.pos[last].wind_n_mps - vtas_n).norm(), 1e-12);
}

// Variant key `wind_at_loss: gnss_ins` (keep_gnss_calibration): the denied phase keeps the wind and the air-data
// offsets last given by the joint estimator (here the truth: the scenario's wind, and the offset added to the air
// data) instead of its own GNSS-based wind. The denied velocity is then wind + R(q) v_tas(air - offsets) exactly, and
// in a slow turn after the loss the drift is smaller than with the own wind, which has absorbed the airspeed offset
// for the heading flown before the loss only.
TEST(NavPosition, WindAtLossFromTheJointEstimatorKeepsItsWindAndAirDataOffsets) {
    synth::Scenario sc;
    sc.yaw_rate_rps = 0.01;
    sc.bank_rad = std::atan(0.01 * 30.0 / 9.8);
    const double tas_offset_mps = 0.6;
    test::ChainOptions o;
    o.steps = 35000;
    o.last_fix_step = 15000;
    o.edit = [&](int, synth::Sample& s) { s.air.tas_mps += tas_offset_mps; };
    const test::ChainRun own = test::run_chain(sc, o, 55);
    o.variant = "keep_gnss_calibration";
    const Vec3 offsets(tas_offset_mps, 0.0, 0.0);
    int given = 0;
    o.before_position = [&](int k, PositionFilter& p) {
        if (k > 15000) return;  // the estimator goes on after the loss; what it gives then is not used
        p.set_gnss_ins_calibration(sc.wind_n_mps, offsets);
        ++given;
    };
    const test::ChainRun kept = test::run_chain(sc, o, 55);
    EXPECT_GT(given, 0);
    const std::size_t last = kept.pos.size() - 1;
    ASSERT_TRUE(kept.pos[last].gnss_denied);
    EXPECT_EQ(kept.pos[last].wind_n_mps, sc.wind_n_mps);
    const AirDataEstimate& a = kept.air[last];
    const Vec3 vtas_n = kept.att[last].q_nb * math::vtas_body(a.tas_mps - tas_offset_mps, a.aoa_rad, a.aos_rad);
    EXPECT_LT((kept.pos[last].v_n_mps - kept.pos[last].wind_n_mps - vtas_n).norm(), 1e-12);
    std::printf("horizontal error after 200 s denied: own wind %.1f m, the estimator's %.1f m\n",
                test::hor_error_m(own, last), test::hor_error_m(kept, last));
    EXPECT_LT(test::hor_error_m(kept, last), 0.5 * test::hor_error_m(own, last));
}
