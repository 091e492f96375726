// Missions from YAML: the example files, and every kind of error names the offending key.
#include <gtest/gtest.h>

#include <string>

#include "gnc/mission_yaml.hpp"
#include "guidance/model/scenario_missions.hpp"

using namespace gdnav::guidance;
using gdnav::config::Config;
using gdnav::config::ConfigError;
using gdnav::gnc::AileronMode;
using gdnav::gnc::ElevatorMode;
using gdnav::math::deg2rad;

namespace {

const std::string kFirst = R"(
name: t
t_end_s: 100
operations:
  - op: hold
    throttle: {mode: airspeed, airspeed_mps: 29}
    elevator: {mode: pressure_altitude, pressure_altitude_m: 1000}
    aileron: {mode: bearing, bearing_deg: 20}
    rudder: {mode: sideslip, sideslip_deg: 0}
    until: {trigger: time, t_s: 10}
)";

Mission parse(const std::string& yaml) { return parse_mission(Config::parse(yaml, "mission.yaml")); }

// Error message of parsing `yaml`, or "" when it parses.
std::string error_of(const std::string& yaml) {
    try {
        parse(yaml);
    } catch (const ConfigError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(MissionYaml, Scenario1ExampleMatchesBuilder) {
    const Mission m = load_mission(GDNAV_CONFIG_DIR "/missions/scenario1_example.yaml");
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
    const Mission ref = make_scenario1_mission(d);
    EXPECT_EQ(m.t_end_s, 3800.0);
    ASSERT_EQ(m.operations.size(), ref.operations.size());
    for (std::size_t i = 0; i < ref.operations.size(); ++i) {
        SCOPED_TRACE(i);
        const auto& a = m.operations[i];
        const auto& b = ref.operations[i];
        EXPECT_EQ(a.targets.throttle_mode, b.targets.throttle_mode);
        EXPECT_NEAR(a.targets.throttle_target, b.targets.throttle_target, 1e-12);
        EXPECT_EQ(a.targets.elevator_mode, b.targets.elevator_mode);
        EXPECT_NEAR(a.targets.elevator_target, b.targets.elevator_target, 1e-12);
        EXPECT_EQ(a.targets.aileron_mode, b.targets.aileron_mode);
        EXPECT_NEAR(a.targets.aileron_target, b.targets.aileron_target, 1e-12);
        EXPECT_EQ(a.targets.rudder_mode, b.targets.rudder_mode);
        EXPECT_EQ(a.trigger.kind, b.trigger.kind);
        EXPECT_NEAR(a.trigger.value, b.trigger.value, 1e-12);
    }
}

TEST(MissionYaml, Scenario2ExampleHasEightTurns) {
    const Mission m = load_mission(GDNAV_CONFIG_DIR "/missions/scenario2_example.yaml");
    EXPECT_EQ(m.t_end_s, 500.0);
    ASSERT_EQ(m.operations.size(), 17u);
    int turns = 0;
    for (const auto& op : m.operations) turns += op.targets.aileron_mode == AileronMode::bank ? 1 : 0;
    EXPECT_EQ(turns, 8);
    // Turn 5: 150 -> -170 deg is +40 deg: right through 180, crossing at -175 deg.
    EXPECT_NEAR(m.operations[9].targets.aileron_target, deg2rad(10.0), 1e-15);
    EXPECT_NEAR(m.operations[9].trigger.value, deg2rad(-175.0), 1e-12);
    // Turn 4: -90 -> 150 deg is -120 deg: left.
    EXPECT_NEAR(m.operations[7].targets.aileron_target, deg2rad(-10.0), 1e-15);
    EXPECT_EQ(m.operations[16].trigger.kind, TriggerKind::time);
}

TEST(MissionYaml, DegreesBecomeRadiansAndChannelsCarryOver) {
    const Mission m = parse(kFirst + R"(
  - op: hold
    aileron: {mode: bank, bank_deg: -15}
    elevator: {mode: pitch, pitch_deg: 3}
    until: {trigger: heading, heading_deg: 45}
  - op: airspeed_change
    to_airspeed_mps: 27
    until: {trigger: end}
)");
    ASSERT_EQ(m.operations.size(), 3u);
    EXPECT_NEAR(m.operations[0].targets.aileron_target, deg2rad(20.0), 1e-15);
    EXPECT_EQ(m.operations[1].targets.throttle_target, 29.0);  // carried over
    EXPECT_EQ(m.operations[1].targets.elevator_mode, ElevatorMode::pitch);
    EXPECT_NEAR(m.operations[1].targets.elevator_target, deg2rad(3.0), 1e-15);
    EXPECT_NEAR(m.operations[1].targets.aileron_target, deg2rad(-15.0), 1e-15);
    EXPECT_EQ(m.operations[1].trigger.kind, TriggerKind::heading);
    EXPECT_NEAR(m.operations[1].trigger.value, deg2rad(45.0), 1e-15);
    EXPECT_EQ(m.operations[2].targets.throttle_target, 27.0);
    EXPECT_EQ(m.operations[2].targets.aileron_mode, AileronMode::bank);  // carried over
    EXPECT_EQ(m.operations[2].trigger.kind, TriggerKind::end);
}

TEST(MissionYaml, UnknownOperationNamesKey) {
    const auto e = error_of(kFirst + "  - {op: loop, until: {trigger: end}}\n");
    EXPECT_NE(e.find("'operations[1].op'"), std::string::npos) << e;
    EXPECT_NE(e.find("loop"), std::string::npos) << e;
}

TEST(MissionYaml, UnknownModeAndTriggerNameKey) {
    std::string y = kFirst;
    y.replace(y.find("mode: bearing"), 13, "mode: roll");
    auto e = error_of(y);
    EXPECT_NE(e.find("'operations[0].aileron.mode'"), std::string::npos) << e;
    e = error_of(kFirst + "  - {op: hold, until: {trigger: sunset}}\n");
    EXPECT_NE(e.find("'operations[1].until.trigger'"), std::string::npos) << e;
}

TEST(MissionYaml, MissingKeysNameKey) {
    std::string y = kFirst;
    y.erase(y.find("    rudder:"), y.find("    until:") - y.find("    rudder:"));
    auto e = error_of(y);
    EXPECT_NE(e.find("'operations[0].rudder'"), std::string::npos) << e;
    EXPECT_NE(e.find("missing"), std::string::npos) << e;
    e = error_of(kFirst + "  - {op: turn, to_bearing_deg: 60, bank_deg: 10}\n");
    EXPECT_NE(e.find("'operations[1].until'"), std::string::npos) << e;
    e = error_of(kFirst + "  - {op: turn, to_bearing_deg: 60, until: {trigger: end}}\n");
    EXPECT_NE(e.find("'operations[1].bank_deg'"), std::string::npos) << e;
    e = error_of(kFirst + "  - {op: hold, until: {trigger: elapsed}}\n");
    EXPECT_NE(e.find("'operations[1].until.dt_s'"), std::string::npos) << e;
    e = error_of("name: t\noperations: []\n");
    EXPECT_NE(e.find("'t_end_s'"), std::string::npos) << e;
}

TEST(MissionYaml, OutOfRangeValuesNameKey) {
    auto e = error_of(kFirst + "  - {op: turn, to_bearing_deg: 60, bank_deg: 45, until: {trigger: end}}\n");
    EXPECT_NE(e.find("'operations[1].bank_deg'"), std::string::npos) << e;
    EXPECT_NE(e.find("45"), std::string::npos) << e;
    e = error_of(kFirst + "  - {op: hold, aileron: {mode: bank, bank_deg: -31}, until: {trigger: end}}\n");
    EXPECT_NE(e.find("'operations[1].aileron.bank_deg'"), std::string::npos) << e;
    e = error_of(kFirst + "  - {op: airspeed_change, to_airspeed_mps: 290, until: {trigger: end}}\n");
    EXPECT_NE(e.find("'operations[1].to_airspeed_mps'"), std::string::npos) << e;
    e = error_of(kFirst + "  - {op: turn, to_bearing_deg: 181, bank_deg: 10, until: {trigger: end}}\n");
    EXPECT_NE(e.find("'operations[1].to_bearing_deg'"), std::string::npos) << e;
}

TEST(MissionYaml, InconsistentManoeuvresNameKey) {
    // The first operation must set every channel.
    auto e = error_of("name: t\nt_end_s: 10\noperations:\n  - {op: turn, to_bearing_deg: 5, bank_deg: 10, "
                      "until: {trigger: end}}\n");
    EXPECT_NE(e.find("'operations[0].op'"), std::string::npos) << e;
    // A turn of 3 deg cannot end 5 deg before its target.
    e = error_of(kFirst + "  - {op: turn, to_bearing_deg: 23, bank_deg: 10, until: {trigger: end}}\n");
    EXPECT_NE(e.find("'operations[1].to_bearing_deg'"), std::string::npos) << e;
    // Automatic turn direction needs a held bearing.
    e = error_of(kFirst + "  - {op: hold, aileron: {mode: bank, bank_deg: 5}, until: {trigger: end}}\n" +
                 "  - {op: turn, to_bearing_deg: 90, bank_deg: 10, until: {trigger: end}}\n");
    EXPECT_NE(e.find("'operations[2].direction'"), std::string::npos) << e;
    // An explicit direction is accepted instead.
    EXPECT_EQ(error_of(kFirst + "  - {op: hold, aileron: {mode: bank, bank_deg: 5}, until: {trigger: end}}\n" +
                       "  - {op: turn, to_bearing_deg: 90, bank_deg: 10, direction: left, until: {trigger: end}}\n"),
              "");
    // A climb "down" contradicts the held pressure altitude.
    e = error_of(kFirst + "  - {op: altitude_change, to_pressure_altitude_m: 900, path_angle_deg: 2, direction: "
                          "climb, until: {trigger: end}}\n");
    EXPECT_NE(e.find("'operations[1].to_pressure_altitude_m'"), std::string::npos) << e;
}

TEST(MissionYaml, UnknownKeysAreRejected) {
    std::string y = kFirst;
    y.replace(y.find("t_s: 10"), 7, "t_s: 10, dt_s: 3");
    auto e = error_of(y);
    EXPECT_NE(e.find("'operations[0].until.dt_s': unknown key"), std::string::npos) << e;
    e = error_of(kFirst + "t_end: 5\n");
    EXPECT_NE(e.find("'t_end': unknown key"), std::string::npos) << e;
    e = error_of(kFirst + "  - {op: hold, aileron: {mode: bearing, bank_deg: 5}, until: {trigger: end}}\n");
    EXPECT_NE(e.find("'operations[1].aileron.bearing_deg'"), std::string::npos) << e;
}

TEST(MissionYaml, MissingFileIsConfigError) {
    EXPECT_THROW(load_mission("/nonexistent/mission.yaml"), ConfigError);
}
