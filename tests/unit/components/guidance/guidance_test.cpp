// Guidance sequencing: operations start and end at the steps predicted by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "guidance/model/guidance.hpp"
#include "guidance/model/scenario_missions.hpp"

using namespace gdnav::guidance;
using gdnav::gnc::AileronMode;
using gdnav::gnc::ChannelTargets;
using gdnav::gnc::ElevatorMode;
using gdnav::math::deg2rad;

namespace {

constexpr double kDt = 0.01;

ChannelTargets level(double v, double hp, double chi_rad) {
    ChannelTargets t;
    t.throttle_target = v;
    t.elevator_mode = ElevatorMode::pressure_altitude;
    t.elevator_target = hp;
    t.aileron_mode = AileronMode::bearing;
    t.aileron_target = chi_rad;
    return t;
}

}  // namespace

TEST(Guidance, TimeAndElapsedSequence) {
    MissionBuilder b("seq", 3.0, level(28.0, 1000.0, 0.0));
    b.hold(Trigger::time(1.0)).change_airspeed(30.0, Trigger::elapsed(0.5)).change_airspeed(32.0, Trigger::end());
    Guidance g(b.build());
    NavState est;
    for (int k = 0; k <= 400; ++k) {
        const GuidanceOutput out = g.step(k * kDt, est);
        const std::uint32_t expected_op = k < 100 ? 0 : (k < 150 ? 1 : 2);
        ASSERT_EQ(out.operation, expected_op) << "k = " << k;
        EXPECT_EQ(out.targets.throttle_target, expected_op == 0 ? 28.0 : (expected_op == 1 ? 30.0 : 32.0));
        EXPECT_EQ(out.finished, k >= 300) << "k = " << k;
        if (k == 150) {
            EXPECT_DOUBLE_EQ(g.operation_start_s(), 1.5);
        }
    }
}

TEST(Guidance, OperationsWhoseTimeHasPassedEndAtOnce) {
    MissionBuilder b("cascade", 10.0, level(28.0, 1000.0, 0.0));
    b.hold(Trigger::time(0.0)).change_airspeed(29.0, Trigger::time(0.5)).change_airspeed(30.0, Trigger::end());
    Guidance g(b.build());
    const GuidanceOutput out = g.step(1.0, NavState{});  // first call at t = 1 s: ops 0 and 1 are already over
    EXPECT_EQ(out.operation, 2u);
    EXPECT_EQ(out.targets.throttle_target, 30.0);
    EXPECT_FALSE(out.finished);
}

TEST(Guidance, LastTriggerFinishesAndKeepsLastTargets) {
    MissionBuilder b("short", 100.0, level(28.0, 1000.0, 0.0));
    b.hold(Trigger::elapsed(0.2)).change_airspeed(31.0, Trigger::pressure_altitude(1010.0));
    Guidance g(b.build());
    NavState est;
    est.pressure_altitude_m = 1000.0;
    GuidanceOutput out;
    for (int k = 0; k < 50; ++k) out = g.step(k * kDt, est);
    EXPECT_EQ(out.operation, 1u);
    EXPECT_FALSE(out.finished);
    est.pressure_altitude_m = 1010.5;
    out = g.step(0.5, est);
    EXPECT_TRUE(out.finished);
    EXPECT_EQ(out.operation, 1u);
    EXPECT_EQ(out.targets.throttle_target, 31.0);
    out = g.step(0.51, est);
    EXPECT_TRUE(out.finished);
    EXPECT_EQ(out.operation, 1u);
}

TEST(Guidance, RejectsMissionsThatCannotBeFlown) {
    Mission empty{"empty", 10.0, {}};
    EXPECT_THROW(Guidance{empty}, std::invalid_argument);
    Mission m{"m", 10.0, {Operation{level(28.0, 1000.0, 0.0), Trigger::elapsed(0.0)}}};
    EXPECT_THROW(Guidance{m}, std::invalid_argument);
    m.operations[0].trigger = Trigger::end();
    m.operations[0].targets.aileron_mode = static_cast<AileronMode>(0);  // not a mode
    EXPECT_THROW(Guidance{m}, std::invalid_argument);
    m.operations[0].targets.aileron_mode = AileronMode::bank;
    m.operations[0].targets.elevator_target = std::nan("");
    EXPECT_THROW(Guidance{m}, std::invalid_argument);
}

// Scenario #1 flown by a kinematic stand-in for the aircraft + navigation: airspeed and held bearing / pressure
// altitude follow their targets at once; in bank mode chi turns at g tan(xi) / V; in air-path-angle mode Hp
// changes at V sin(gamma). The operation changes must come at the steps computed by hand from these rates.
TEST(Guidance, Scenario1SequenceOnKinematicPlant) {
    Scenario1Draws d;
    d.bearing_ini_rad = deg2rad(-72.0);
    d.bearing_end_rad = deg2rad(-56.0);
    d.airspeed_delay_s = 491.0;
    d.airspeed_ini_mps = 29.13;
    d.airspeed_end_mps = 31.0;
    d.altitude_delay_s = 454.0;
    d.pressure_altitude_ini_m = 2557.1;
    d.pressure_altitude_end_m = 2811.0;
    d.turn_time_s = 192.6;
    Guidance g(make_scenario1_mission(d));

    const double g0 = 9.80665;
    double chi = d.bearing_ini_rad, hp = d.pressure_altitude_ini_m;
    long start[6] = {0, -1, -1, -1, -1, -1};
    long finished_at = -1;
    for (long k = 0; k <= 390000 && finished_at < 0; ++k) {
        NavState est;
        est.ground_bearing_rad = chi;
        est.pressure_altitude_m = hp;
        const GuidanceOutput out = g.step(static_cast<double>(k) * kDt, est);
        if (start[out.operation] < 0) start[out.operation] = k;
        if (out.finished) finished_at = k;
        const auto& t = out.targets;
        if (t.aileron_mode == AileronMode::bank) chi += g0 * std::tan(t.aileron_target) / t.throttle_target * kDt;
        else chi = t.aileron_target;
        if (t.elevator_mode == ElevatorMode::air_path_angle) hp += t.throttle_target * std::sin(t.elevator_target) * kDt;
        else hp = t.elevator_target;
    }
    // op 1 (bank +10 deg) at t >= 192.6 s.
    EXPECT_EQ(start[1], 19260);
    // op 2 when chi has turned 11 deg (from -72 to the crossing bearing -61): n steps of rate * dt.
    const double rate = g0 * std::tan(deg2rad(10.0)) / 29.13;
    const long n_turn = static_cast<long>(std::ceil(deg2rad(11.0) / (rate * kDt)));
    EXPECT_NEAR(start[2], start[1] + n_turn, 1);
    // op 3 491 s and op 4 454 s later (exact step counts).
    EXPECT_EQ(start[3], start[2] + 49100);
    EXPECT_EQ(start[4], start[3] + 45400);
    // op 5 when Hp has climbed 253.9 m at 31 sin(2 deg) m/s.
    const long n_climb = static_cast<long>(std::ceil(253.9 / (31.0 * std::sin(deg2rad(2.0)) * kDt)));
    EXPECT_NEAR(start[5], start[4] + n_climb, 1);
    EXPECT_EQ(finished_at, 380000);
}
