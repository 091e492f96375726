// Scenario mission builders and draws (docs/guidance-control.md, "Scenario missions": tables and draw rules).
#include <gtest/gtest.h>

#include <cmath>

#include "guidance/model/scenario_missions.hpp"

using namespace gdnav::guidance;
using gdnav::gnc::AileronMode;
using gdnav::gnc::ElevatorMode;
using gdnav::gnc::RudderMode;
using gdnav::gnc::ThrottleMode;
using gdnav::math::deg2rad;
using gdnav::math::rad2deg;

namespace {

Scenario1Draws seed1_like() {
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
    return d;
}

void expect_op(const Operation& op, double v, ElevatorMode em, double e, AileronMode am, double a, TriggerKind tk,
               double tv, const char* what) {
    SCOPED_TRACE(what);
    EXPECT_EQ(op.targets.throttle_mode, ThrottleMode::airspeed);
    EXPECT_DOUBLE_EQ(op.targets.throttle_target, v);
    EXPECT_EQ(op.targets.elevator_mode, em);
    EXPECT_NEAR(op.targets.elevator_target, e, 1e-12);
    EXPECT_EQ(op.targets.aileron_mode, am);
    EXPECT_NEAR(op.targets.aileron_target, a, 1e-12);
    EXPECT_EQ(op.targets.rudder_mode, RudderMode::sideslip);
    EXPECT_EQ(op.targets.rudder_target, 0.0);
    EXPECT_EQ(op.trigger.kind, tk);
    EXPECT_NEAR(op.trigger.value, tv, 1e-12);
}

}  // namespace

TEST(ScenarioMissions, Scenario1OperationTable) {
    const Scenario1Draws d = seed1_like();
    const Mission m = make_scenario1_mission(d);
    ASSERT_EQ(m.operations.size(), 6u);
    EXPECT_EQ(m.t_end_s, 3800.0);
    const auto& o = m.operations;
    const auto P = ElevatorMode::pressure_altitude;
    const auto C = AileronMode::bearing;
    expect_op(o[0], 29.13, P, 2557.1, C, deg2rad(-72), TriggerKind::time, 192.6, "op0 hold chi_ini");
    expect_op(o[1], 29.13, P, 2557.1, AileronMode::bank, deg2rad(10), TriggerKind::bearing, deg2rad(-61), "op1 turn");
    expect_op(o[2], 29.13, P, 2557.1, C, deg2rad(-56), TriggerKind::elapsed, 491.0, "op2 hold chi_end");
    expect_op(o[3], 31.0, P, 2557.1, C, deg2rad(-56), TriggerKind::elapsed, 454.0, "op3 V_end");
    expect_op(o[4], 31.0, ElevatorMode::air_path_angle, deg2rad(2), C, deg2rad(-56), TriggerKind::pressure_altitude,
              2811.0, "op4 climb");
    expect_op(o[5], 31.0, P, 2811.0, C, deg2rad(-56), TriggerKind::time, 3800.0, "op5 hold Hp_end");
    const auto init = initial_flight(m);
    ASSERT_TRUE(init.has_value());
    EXPECT_EQ(init->airspeed_mps, 29.13);
    EXPECT_EQ(init->pressure_altitude_m, 2557.1);
    EXPECT_NEAR(init->bearing_rad, deg2rad(-72), 1e-15);
}

TEST(ScenarioMissions, Scenario1LeftTurnAndDescent) {
    Scenario1Draws d = seed1_like();
    d.bearing_ini_rad = deg2rad(10.0);
    d.bearing_end_rad = deg2rad(-20.0);  // left turn: bank -10, crossing at -20 + 5 = -15
    d.pressure_altitude_end_m = 2300.0;  // descent: gamma -2
    const Mission m = make_scenario1_mission(d);
    EXPECT_NEAR(m.operations[1].targets.aileron_target, deg2rad(-10), 1e-15);
    EXPECT_NEAR(m.operations[1].trigger.value, deg2rad(-15), 1e-12);
    EXPECT_NEAR(m.operations[4].targets.elevator_target, deg2rad(-2), 1e-15);
}

TEST(ScenarioMissions, Scenario1TurnAcross180) {
    Scenario1Draws d = seed1_like();
    d.bearing_ini_rad = deg2rad(170.0);
    d.bearing_end_rad = deg2rad(-170.0);  // +20 deg wrapped: right turn through 180, crossing at -175
    const Mission m = make_scenario1_mission(d);
    EXPECT_NEAR(m.operations[1].targets.aileron_target, deg2rad(10), 1e-15);
    EXPECT_NEAR(m.operations[1].trigger.value, deg2rad(-175), 1e-12);
}

TEST(ScenarioMissions, Scenario2OperationTable) {
    Scenario2Draws d;
    d.common = seed1_like();
    d.leg_s = {30, 20, 45, 15, 40, 25, 35};
    const double chi_deg[8] = {-56, 10, -90, 150, -170, 120, 60, -20};
    for (int k = 0; k < 7; ++k) d.bearing_rad[k] = deg2rad(chi_deg[k + 1]);
    const Mission m = make_scenario2_mission(d);
    ASSERT_EQ(m.operations.size(), 17u);
    EXPECT_EQ(m.t_end_s, 500.0);
    const auto P = ElevatorMode::pressure_altitude;
    expect_op(m.operations[0], 29.13, P, 2557.1, AileronMode::bearing, deg2rad(-72), TriggerKind::time, 192.6, "op0");
    double previous = -72.0;
    for (int k = 0; k < 8; ++k) {
        double change = chi_deg[k] - previous;
        change -= 360.0 * std::round(change / 360.0);
        const double bank = change > 0 ? 10.0 : -10.0;
        const double crossing = chi_deg[k] - (change > 0 ? 5.0 : -5.0);
        const Operation& turn = m.operations[1 + 2 * k];
        const Operation& hold = m.operations[2 + 2 * k];
        expect_op(turn, 29.13, P, 2557.1, AileronMode::bank, deg2rad(bank), TriggerKind::bearing,
                  gdnav::math::wrap_pi(deg2rad(crossing)), "turn");
        if (k < 7)
            expect_op(hold, 29.13, P, 2557.1, AileronMode::bearing, deg2rad(chi_deg[k]), TriggerKind::elapsed,
                      d.leg_s[k], "hold");
        else
            expect_op(hold, 29.13, P, 2557.1, AileronMode::bearing, deg2rad(chi_deg[k]), TriggerKind::time, 500.0,
                      "last hold");
        previous = chi_deg[k];
    }
}

TEST(ScenarioMissions, DrawsRespectTheirRules) {
    const int n = 2000;
    double sum_v = 0, sum_hp = 0, sum_turn = 0, sum_turn2 = 0;
    for (int i = 0; i < n; ++i) {
        gdnav::rnd::Stream s = gdnav::rnd::Stream::derive(7, static_cast<std::uint64_t>(i), "guidance");
        const Scenario1Draws d = draw_scenario1(s);
        const double chi0 = rad2deg(d.bearing_ini_rad), chi1 = rad2deg(d.bearing_end_rad);
        EXPECT_NEAR(chi0, std::round(chi0), 1e-9);
        EXPECT_GE(std::round(chi0), -179.0);
        EXPECT_LE(std::round(chi0), 180.0);
        EXPECT_GE(std::fabs(rad2deg(gdnav::math::wrap_pi(d.bearing_end_rad - d.bearing_ini_rad))), 10.0 - 1e-9);
        EXPECT_NEAR(chi1, std::round(chi1), 1e-9);
        EXPECT_GE(d.airspeed_delay_s, 150.0);
        EXPECT_GE(d.airspeed_ini_mps, 24.0);
        EXPECT_LE(d.airspeed_ini_mps, 34.0);
        EXPECT_GE(std::fabs(d.airspeed_end_mps - d.airspeed_ini_mps), 0.5);
        EXPECT_GE(d.airspeed_end_mps, 24.0);
        EXPECT_LE(d.airspeed_end_mps, 34.0);
        EXPECT_GE(d.altitude_delay_s, 150.0);
        EXPECT_LE(d.airspeed_delay_s + d.altitude_delay_s, 2500.0);
        EXPECT_GE(std::fabs(d.pressure_altitude_end_m - d.pressure_altitude_ini_m), 100.0);
        EXPECT_GE(d.turn_time_s, 115.0);
        sum_v += d.airspeed_ini_mps;
        sum_hp += d.pressure_altitude_ini_m;
        sum_turn += d.turn_time_s;
        sum_turn2 += d.turn_time_s * d.turn_time_s;
        // Every drawn mission must be buildable (turn larger than the lead, etc.).
        EXPECT_NO_THROW(make_scenario1_mission(d));
    }
    // Means: V_ini ~ N(29, 1.5^2) truncated symmetrically -> 29 (3 sigma of the mean: 0.1); Hp_ini ~ N(2700, 200^2)
    // (3 sigma: 13.4). t_turn ~ N(130, 50^2) truncated at 115 (a = -0.3): mean = 130 + 50 phi(0.3)/(1 - Phi(-0.3))
    // = 130 + 50 * 0.381388 / 0.617911 = 160.86 s, sd = 50 sqrt(1 + a phi/(1-Phi) - (phi/(1-Phi))^2) = 32.9 s.
    EXPECT_NEAR(sum_v / n, 29.0, 0.1);
    EXPECT_NEAR(sum_hp / n, 2700.0, 15.0);
    const double mean_turn = sum_turn / n;
    EXPECT_NEAR(mean_turn, 160.86, 2.5);
    EXPECT_NEAR(std::sqrt(sum_turn2 / n - mean_turn * mean_turn), 32.9, 2.0);
}

TEST(ScenarioMissions, Scenario2RepeatsScenario1DrawsThenDrawsLegsAndBearings) {
    for (std::uint64_t i = 0; i < 300; ++i) {
        gdnav::rnd::Stream s1 = gdnav::rnd::Stream::derive(3, i, "guidance");
        gdnav::rnd::Stream s2 = gdnav::rnd::Stream::derive(3, i, "guidance");
        const Scenario1Draws a = draw_scenario1(s1);
        const Scenario2Draws b = draw_scenario2(s2);
        EXPECT_EQ(a.bearing_ini_rad, b.common.bearing_ini_rad);
        EXPECT_EQ(a.bearing_end_rad, b.common.bearing_end_rad);
        EXPECT_EQ(a.airspeed_ini_mps, b.common.airspeed_ini_mps);
        EXPECT_EQ(a.pressure_altitude_ini_m, b.common.pressure_altitude_ini_m);
        EXPECT_EQ(a.turn_time_s, b.common.turn_time_s);
        for (double leg : b.leg_s) {
            EXPECT_EQ(leg, std::round(leg));
            EXPECT_GE(leg, 10.0);
            EXPECT_LE(leg, 50.0);
        }
        double previous = b.common.bearing_end_rad;
        for (double chi : b.bearing_rad) {
            EXPECT_GE(std::fabs(rad2deg(gdnav::math::wrap_pi(chi - previous))), 10.0 - 1e-9);
            previous = chi;
        }
        const Mission m = make_scenario2_mission(b);
        EXPECT_EQ(m.operations.size(), 17u);
    }
}
