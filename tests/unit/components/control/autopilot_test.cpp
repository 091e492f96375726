// Autopilot: configuration file = the gain tables of docs/guidance-control.md ("Control"), loop measurements, rate,
// first actions computed by hand, mode resets.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "autopilot_test_support.hpp"
#include "control/model/autopilot.hpp"

using namespace gdnav::control;
using namespace gdnav::control::test;
using gdnav::config::Config;
using gdnav::config::ConfigError;
using gdnav::gnc::AileronMode;
using gdnav::gnc::ElevatorMode;
using gdnav::guidance::GuidanceOutput;
using gdnav::math::deg2rad;
using gdnav::math::rad2deg;

namespace {

const char* kFile = kAutopilotFile;

ControlEstimates level_estimate(double v, double theta_deg, double hp) {
    ControlEstimates e;
    e.airspeed_mps = v;
    e.q_nb = gdnav::math::quat_from_euler({0.0, deg2rad(theta_deg), 0.0});
    e.v_n_mps = {v, 0.0, 0.0};
    e.pressure_altitude_m = hp;
    e.altitude_m = hp;
    return e;
}

}  // namespace

TEST(AutopilotConfig, FileHoldsReferenceGains) {
    const AutopilotConfig c = read_autopilot_config(Config::load(kFile));
    EXPECT_DOUBLE_EQ(c.control_period_s(), 0.02);
    EXPECT_DOUBLE_EQ(c.derivative_filter_time_s, 16 * 0.02);
    EXPECT_EQ(c.initial_throttle, 0.3);
    // Primary loops (K_i = 0.01 K_p; K_d = 0.3 K_p, 0.9 K_p for pitch).
    EXPECT_EQ(c.throttle_airspeed.kp, 0.06);
    EXPECT_NEAR(c.throttle_airspeed.ki, 0.01 * 0.06, 1e-18);
    EXPECT_NEAR(c.throttle_airspeed.kd, 0.3 * 0.06, 1e-18);
    EXPECT_EQ(c.throttle_airspeed.u_eq, 0.5);
    EXPECT_EQ(c.throttle_airspeed.u_max, 1.0);
    EXPECT_EQ(c.elevator_pitch.kp, -0.8);
    EXPECT_NEAR(c.elevator_pitch.kd, 0.9 * -0.8, 1e-15);
    EXPECT_EQ(c.elevator_pitch.u_max, 8.0);
    EXPECT_EQ(c.aileron_bank.kp, 0.3);
    EXPECT_EQ(c.rudder_sideslip.kp, -0.04);
    // Outer loops.
    EXPECT_EQ(c.pressure_altitude.kd, 15.0);
    EXPECT_EQ(c.pressure_altitude.u_max, 7.0);
    EXPECT_EQ(c.altitude.kd, 400.0);
    EXPECT_EQ(c.air_path_angle.u_min, -20.0);
    EXPECT_EQ(c.bearing.kp, 2.0);
    EXPECT_EQ(c.bearing.u_max, 15.0);
    EXPECT_EQ(c.heading.kp, 0.2);
    EXPECT_EQ(c.air_bank.kp, 1.5);
    // Ramps.
    EXPECT_EQ(c.ramp_steps(gdnav::gnc::ThrottleMode::airspeed), 8.0);
    EXPECT_EQ(c.ramp_steps(ElevatorMode::pressure_altitude), 32.0);
    EXPECT_EQ(c.ramp_steps(AileronMode::bank), 64.0);
    EXPECT_EQ(c.ramp_steps(AileronMode::bearing), 16.0);
    EXPECT_EQ(c.ramp_steps(gdnav::gnc::RudderMode::sideslip), 8.0);
    EXPECT_EQ(c.coupling_gain_deg_per_mps, 0.2);
}

TEST(AutopilotConfig, BadValuesNameKey) {
    auto error_of = [](const std::string& from, const std::string& to) {
        std::ifstream in(kFile);
        std::stringstream ss;
        ss << in.rdbuf();
        std::string text = ss.str();
        const auto pos = text.find(from);
        EXPECT_NE(pos, std::string::npos) << from;
        text.replace(pos, from.size(), to);
        try {
            read_autopilot_config(Config::parse(text, "autopilot.yaml"));
        } catch (const ConfigError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    auto e = error_of("limit_deg: 7", "limit_deg: -7");
    EXPECT_NE(e.find("'secondary.pressure_altitude.limit_deg'"), std::string::npos) << e;
    e = error_of("period_ticks: 2", "period_ticks: 0");
    EXPECT_NE(e.find("'timing.period_ticks'"), std::string::npos) << e;
    e = error_of("bank_airspeed_coupling:", "extra_gain: 3\nbank_airspeed_coupling:");
    EXPECT_NE(e.find("'extra_gain': unknown key"), std::string::npos) << e;
    e = error_of("u_max: 1.0", "u_max: 1.5");
    EXPECT_NE(e.find("'primary.throttle_airspeed.u_max'"), std::string::npos) << e;
}

TEST(Measurements, AnglesFromEstimates) {
    ControlEstimates e;
    e.airspeed_mps = 30.0;
    e.aoa_rad = deg2rad(4.0);
    e.aos_rad = deg2rad(2.0);
    e.q_nb = gdnav::math::quat_from_euler({deg2rad(30.0), deg2rad(5.0), deg2rad(-10.0)});
    e.v_n_mps = {-3.0, 4.0, 0.5};
    const LoopMeasurements m = measure(e);
    EXPECT_NEAR(rad2deg(m.heading_rad), 30.0, 1e-12);
    EXPECT_NEAR(rad2deg(m.pitch_rad), 5.0, 1e-12);
    EXPECT_NEAR(rad2deg(m.bank_rad), -10.0, 1e-12);
    EXPECT_NEAR(m.ground_bearing_rad, std::atan2(4.0, -3.0), 1e-15);
    EXPECT_EQ(m.sideslip_rad, e.aos_rad);
    // The air-path bearing and angle are those of the airspeed vector in NED: v = R_nb v_tas_b.
    const gdnav::math::Vec3 v = e.q_nb * gdnav::math::vtas_body(30.0, e.aoa_rad, e.aos_rad);
    EXPECT_NEAR(m.air_bearing_rad, std::atan2(v.y(), v.x()), 1e-12);
    EXPECT_NEAR(m.air_path_angle_rad, -std::asin(v.z() / 30.0), 1e-12);
    // With alpha = beta = 0 the wind axes are the body axes: mu_TAS = bank.
    e.aoa_rad = e.aos_rad = 0.0;
    EXPECT_NEAR(measure(e).air_bank_rad, deg2rad(-10.0), 1e-12);
    // Wings level, no sideslip: gamma_TAS = theta - alpha.
    e.q_nb = gdnav::math::quat_from_euler({deg2rad(30.0), deg2rad(5.0), 0.0});
    e.aoa_rad = deg2rad(3.0);
    EXPECT_NEAR(rad2deg(measure(e).air_path_angle_rad), 2.0, 1e-12);
}

TEST(Autopilot, ActsEverySecondStepAndHoldsInBetween) {
    Autopilot ap = make_autopilot();
    const ControlEstimates est = level_estimate(28.0, 2.0, 1000.0);
    ap.initialize(est);
    const GuidanceOutput g = targets(30.0, ElevatorMode::pitch, deg2rad(3.0), AileronMode::bank, 0.0);
    const ControlOutput c0 = ap.step(0, g, est);
    EXPECT_EQ(c0.throttle, 0.3);
    EXPECT_EQ(c0.elevator_rad, 0.0);
    const ControlOutput c1 = ap.step(1, g, est);
    EXPECT_EQ(c1.throttle, 0.3);
    const ControlOutput c2 = ap.step(2, g, est);
    EXPECT_NE(c2.throttle, 0.3);
    const ControlOutput c3 = ap.step(3, g, level_estimate(20.0, -5.0, 900.0));  // ignored: held step
    EXPECT_EQ(c3.throttle, c2.throttle);
    EXPECT_EQ(c3.elevator_rad, c2.elevator_rad);
}

TEST(Autopilot, FirstActionByHand) {
    Autopilot ap = make_autopilot();
    const ControlEstimates est = level_estimate(28.0, 2.0, 1000.0);
    ap.initialize(est);
    const ControlOutput c = ap.step(2, targets(30.0, ElevatorMode::pitch, deg2rad(3.0), AileronMode::bank, 0.0), est);
    // Throttle: V_t = (8*28 + 30)/9; e = V_t - 28 = 2/9; I = e; D = e/17.
    const double ev = 2.0 / 9.0;
    EXPECT_NEAR(ap.primary_targets().airspeed_mps, 254.0 / 9.0, 1e-13);
    EXPECT_NEAR(c.throttle, 0.5 + 0.06 * ev + 6e-4 * ev + 0.018 * ev / 17.0, 1e-13);
    // Elevator: theta_t = (32*2 + 3)/33 deg; e = 1/33 deg.
    const double et = 1.0 / 33.0;
    EXPECT_NEAR(rad2deg(c.elevator_rad), -0.8 * et - 0.008 * et - 0.72 * et / 17.0, 1e-12);
    // Ailerons: no bank error; bank-mode coupling 0.2 deg per m/s of (V_t - V).
    EXPECT_NEAR(rad2deg(c.aileron_rad), 0.2 * ev, 1e-12);
    EXPECT_NEAR(c.rudder_rad, 0.0, 1e-15);
}

TEST(Autopilot, NoAirspeedCouplingOutsideBankMode) {
    Autopilot ap = make_autopilot();
    const ControlEstimates est = level_estimate(28.0, 2.0, 1000.0);  // ground bearing 0
    ap.initialize(est);
    const ControlOutput c = ap.step(2, targets(30.0, ElevatorMode::pitch, deg2rad(2.0), AileronMode::bearing, 0.0), est);
    EXPECT_NEAR(c.aileron_rad, 0.0, 1e-15);
}

TEST(Autopilot, PressureAltitudeOuterLoopByHand) {
    Autopilot ap = make_autopilot();
    const ControlEstimates est = level_estimate(29.0, 1.0, 1000.0);
    ap.initialize(est);
    // Target 1 m above: theta_c1 = 0.2*1 + 3e-4*1 + 15*(1/17) deg; theta_t1 = (32*1 + theta_c1)/33.
    GuidanceOutput g = targets(29.0, ElevatorMode::pressure_altitude, 1001.0, AileronMode::bearing, 0.0);
    ap.step(2, g, est);
    const double c1 = 0.2 + 3e-4 + 15.0 / 17.0;
    EXPECT_NEAR(rad2deg(ap.primary_targets().pitch_rad), (32.0 + c1) / 33.0, 1e-12);
    // Second action, same error: I = 2, D = 16/289.
    const double t1 = (32.0 + c1) / 33.0;
    ap.step(4, g, est);
    const double c2 = 0.2 + 6e-4 + 15.0 * 16.0 / 289.0;
    EXPECT_NEAR(rad2deg(ap.primary_targets().pitch_rad), (32.0 * t1 + c2) / 33.0, 1e-12);
    // Large error: the outer output is clamped to 7 deg.
    g.targets.elevator_target = 1100.0;
    g.operation = 1;  // same mode, new operation: the outer state carries on
    const double t2 = rad2deg(ap.primary_targets().pitch_rad);
    ap.step(6, g, est);
    EXPECT_NEAR(rad2deg(ap.primary_targets().pitch_rad), (32.0 * t2 + 7.0) / 33.0, 1e-12);
}

TEST(Autopilot, ModeChangeResetsOuterLoopOnly) {
    Autopilot ap = make_autopilot();
    const ControlEstimates est = level_estimate(29.0, 0.0, 1000.0);
    ap.initialize(est);
    const GuidanceOutput hp = targets(29.0, ElevatorMode::pressure_altitude, 1001.0, AileronMode::bearing, 0.0);
    for (std::uint64_t k = 2; k <= 20; k += 2) ap.step(k, hp, est);  // builds up the outer integral
    // One action in pitch mode (target = current ramp value keeps the ramp still), then back to Hp.
    const double ramp_before = rad2deg(ap.primary_targets().pitch_rad);
    ap.step(22, targets(29.0, ElevatorMode::pitch, deg2rad(ramp_before), AileronMode::bearing, 0.0), est);
    const double ramp = rad2deg(ap.primary_targets().pitch_rad);
    EXPECT_NEAR(ramp, ramp_before, 1e-12);
    ap.step(24, hp, est);
    // The outer loop restarted: its first output is again 0.2 + 3e-4 + 15/17 (I = 1, D = 1/17).
    const double c_restart = 0.2 + 3e-4 + 15.0 / 17.0;
    EXPECT_NEAR(rad2deg(ap.primary_targets().pitch_rad), (32.0 * ramp + c_restart) / 33.0, 1e-12);
}

TEST(Autopilot, BearingErrorIsWrapped) {
    Autopilot ap = make_autopilot();
    ControlEstimates est = level_estimate(29.0, 0.0, 1000.0);
    est.v_n_mps = {-29.0 * std::cos(deg2rad(5.0)), 29.0 * std::sin(deg2rad(5.0)), 0.0};  // chi = 175 deg
    ap.initialize(est);
    // Target -175 deg: the error is +10 deg (right turn through 180), not -350.
    ap.step(2, targets(29.0, ElevatorMode::pitch, 0.0, AileronMode::bearing, deg2rad(-175.0)), est);
    const double c1 = 2.0 * 10.0 + 2e-4 * 10.0 + 0.6 * 10.0 / 17.0;  // 26.35 -> clamped to 15 deg
    EXPECT_GT(c1, 15.0);
    EXPECT_NEAR(rad2deg(ap.primary_targets().bank_rad), 15.0 / 17.0, 1e-12);  // ramp N = 16 from bank 0
}

TEST(Autopilot, RequiresConfigureAndInitialize) {
    Autopilot ap;
    EXPECT_THROW(ap.initialize(ControlEstimates{}), std::logic_error);
    Autopilot ap2 = make_autopilot();
    EXPECT_THROW(ap2.step(2, GuidanceOutput{}, ControlEstimates{}), std::logic_error);
}
