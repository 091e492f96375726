// Trigger evaluation: each trigger must fire at exactly the step predicted by hand from its definition.
#include <gtest/gtest.h>

#include <functional>

#include "guidance/model/trigger.hpp"

using gdnav::guidance::NavState;
using gdnav::guidance::Trigger;
using gdnav::guidance::TriggerState;
using gdnav::math::deg2rad;

namespace {

constexpr double kDt = 0.01;

// Runs a trigger started at step 0 over an estimate that depends on the step; returns the first step at which it
// fires (or -1 within max_steps).
int first_firing_step(const Trigger& trg, const std::function<NavState(int)>& est, int max_steps, int k0 = 0) {
    TriggerState s;
    s.start(trg, k0 * kDt, est(k0));
    for (int k = k0; k <= max_steps; ++k)
        if (s.fired(k * kDt, est(k))) return k;
    return -1;
}

NavState with_bearing_deg(double chi_deg) {
    NavState s;
    s.ground_bearing_rad = gdnav::math::wrap_pi(deg2rad(chi_deg));
    return s;
}

}  // namespace

TEST(Trigger, TimeFiresAtFirstStepAtOrAfterTarget) {
    // t_k = 0.01 k: t >= 1.23 first at k = 123 (despite 123 * 0.01 not being exact in binary).
    EXPECT_EQ(first_firing_step(Trigger::time(1.23), [](int) { return NavState{}; }, 1000), 123);
    EXPECT_EQ(first_firing_step(Trigger::time(1.235), [](int) { return NavState{}; }, 1000), 124);
}

TEST(Trigger, TimeAlreadyPassedFiresAtOnce) {
    EXPECT_EQ(first_firing_step(Trigger::time(1.0), [](int) { return NavState{}; }, 1000, 200), 200);
}

TEST(Trigger, ElapsedCountsFromOperationStart) {
    // Started at k = 500 (t = 5 s): 2.5 s later is k = 750.
    EXPECT_EQ(first_firing_step(Trigger::elapsed(2.5), [](int) { return NavState{}; }, 2000, 500), 750);
}

TEST(Trigger, EndNeverFires) {
    EXPECT_EQ(first_firing_step(Trigger::end(), [](int) { return NavState{}; }, 100000), -1);
}

TEST(Trigger, PressureAltitudeCrossingUpAndDown) {
    // Climb from 1000 m at 1 m per step to 1100 m: Hp >= 1100 first at k = 100.
    auto up = [](int k) {
        NavState s;
        s.pressure_altitude_m = 1000.0 + k;
        return s;
    };
    EXPECT_EQ(first_firing_step(Trigger::pressure_altitude(1100.0), up, 1000), 100);
    // Descent from 1200 m: the start sign is [Hp >= 1100] = true; it changes at the first Hp < 1100, i.e. 1099 m.
    auto down = [](int k) {
        NavState s;
        s.pressure_altitude_m = 1200.0 - k;
        return s;
    };
    EXPECT_EQ(first_firing_step(Trigger::pressure_altitude(1100.0), down, 1000), 101);
    // Moving away never fires.
    EXPECT_EQ(first_firing_step(Trigger::pressure_altitude(900.0), up, 1000), -1);
}

TEST(Trigger, OtherCrossingTriggersUseTheirOwnEstimate) {
    auto rising = [](int k) {
        NavState s;
        s.altitude_m = 500.0 + 0.5 * k;
        s.airspeed_mps = 25.0 + 0.01 * k;
        s.path_angle_rad = deg2rad(-1.0 + 0.01 * k);
        return s;
    };
    EXPECT_EQ(first_firing_step(Trigger::altitude(510.0), rising, 1000), 20);
    EXPECT_EQ(first_firing_step(Trigger::airspeed(26.005), rising, 1000), 101);
    EXPECT_EQ(first_firing_step(Trigger::path_angle(deg2rad(0.505)), rising, 1000), 151);
}

TEST(Trigger, BearingCrossingRightTurnAcross180) {
    // chi = 170 + k deg (right turn through 180); target -175.5 deg (= 184.5): d = wrap(chi - target) = k - 14.5.
    // (Half-degree offsets keep every comparison away from exact equality.)
    EXPECT_EQ(first_firing_step(Trigger::bearing(deg2rad(-175.5)), [](int k) { return with_bearing_deg(170.0 + k); },
                                1000),
              15);
}

TEST(Trigger, BearingCrossingLeftTurnAcross180) {
    // chi = -170 - k deg (left turn); target 175.5: d = 14.5 - k; start sign [d >= 0] = true, first d < 0 at k = 15.
    EXPECT_EQ(first_firing_step(Trigger::bearing(deg2rad(175.5)), [](int k) { return with_bearing_deg(-170.0 - k); },
                                1000),
              15);
}

TEST(Trigger, BearingOppositeCrossingIsIgnored) {
    // Target 0.5 deg; start at -60 deg and keep turning left (1 deg per step): d = -60.5 - k (wrapped). It jumps
    // from -179.5 to +179.5 between k = 119 and 120 (the opposite bearing): that must not fire. Back within 90 deg
    // at k = 210 (d = +89.5) the trigger re-arms with sign true; the real crossing, d < 0, is first at k = 300.
    EXPECT_EQ(first_firing_step(Trigger::bearing(deg2rad(0.5)), [](int k) { return with_bearing_deg(-60.0 - k); }, 1000),
              300);
}

TEST(Trigger, BearingStartedOutsideWindowArmsLater) {
    // Start nearly opposite to the target (d = 179.5), turning right: d = k - 180.5 (k >= 1) enters the window at
    // k = 91 (d = -89.5, arms with sign false) and fires at k = 181 (d = +0.5).
    EXPECT_EQ(first_firing_step(Trigger::bearing(deg2rad(30.5)), [](int k) { return with_bearing_deg(210.0 + k); },
                                1000),
              181);
}

TEST(Trigger, HeadingUsesHeadingEstimate) {
    auto est = [](int k) {
        NavState s;
        s.heading_rad = deg2rad(-20.0 + 0.5 * k);
        s.ground_bearing_rad = deg2rad(100.0);  // ignored by the heading trigger
        return s;
    };
    EXPECT_EQ(first_firing_step(Trigger::heading(deg2rad(5.0)), est, 1000), 50);
}

TEST(Trigger, MakeNavStateAngles) {
    const gdnav::math::Vec3 v_n(-10.0, -10.0, -1.0);  // south-west, climbing
    const auto q = gdnav::math::quat_from_euler({deg2rad(40.0), deg2rad(3.0), deg2rad(-8.0)});
    const NavState s = gdnav::guidance::make_nav_state(30.0, 1500.0, 1520.0, v_n, q);
    EXPECT_NEAR(s.ground_bearing_rad, deg2rad(-135.0), 1e-12);
    EXPECT_NEAR(s.path_angle_rad, std::atan(1.0 / std::sqrt(200.0)), 1e-12);
    EXPECT_NEAR(s.heading_rad, deg2rad(40.0), 1e-12);
    EXPECT_EQ(s.airspeed_mps, 30.0);
    EXPECT_EQ(s.pressure_altitude_m, 1500.0);
    EXPECT_EQ(s.altitude_m, 1520.0);
}
