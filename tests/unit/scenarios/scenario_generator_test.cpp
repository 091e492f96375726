// The paper scenario generators (docs/montecarlo.md, "Scenarios #1 and #2"): streams, explicit values, overrides,
// mission format.
#include <gtest/gtest.h>

#include <cmath>

#include "config/config.hpp"
#include "gnc/mission_yaml.hpp"
#include "paper_scenarios.hpp"
#include "random/stream.hpp"
#include "framework/scenario_generator.hpp"
#include "scenario_yaml.hpp"

using namespace gdnav;
using scenario::generate_paper_scenario;

namespace {

const char* kTemplate = R"(
generator: {name: paper_scenario1}
run: {seed: 3, t0_s: -50, duration_s: 3850}
components:
  flight_physics: {type: flight_physics, initial: {lat_deg: 45, lon_deg: -90, mass_kg: 19.5}}
  gnss: {type: sensors_gnss, suite: sensors/suite.yaml}
  guidance: {type: guidance}
  rec: {type: nav_recorder}
)";

YAML::Node tmpl(const std::string& extra = "") { return YAML::Load(std::string(kTemplate) + extra); }

std::string text(const YAML::Node& n) {
    YAML::Emitter e;
    e << n;
    return e.c_str();
}

double num(const YAML::Node& n) { return n.as<double>(); }

void expect_same_operations(const guidance::Mission& a, const guidance::Mission& b) {
    ASSERT_EQ(a.operations.size(), b.operations.size());
    EXPECT_EQ(a.t_end_s, b.t_end_s);
    for (std::size_t i = 0; i < a.operations.size(); ++i) {
        SCOPED_TRACE(i);
        const auto& x = a.operations[i];
        const auto& y = b.operations[i];
        EXPECT_EQ(x.targets.throttle_mode, y.targets.throttle_mode);
        EXPECT_EQ(x.targets.elevator_mode, y.targets.elevator_mode);
        EXPECT_EQ(x.targets.aileron_mode, y.targets.aileron_mode);
        EXPECT_EQ(x.targets.rudder_mode, y.targets.rudder_mode);
        EXPECT_EQ(x.trigger.kind, y.trigger.kind);
        // Degrees in the file: deg -> rad conversions may differ in the last bit.
        EXPECT_NEAR(x.targets.throttle_target, y.targets.throttle_target, 1e-12);
        EXPECT_NEAR(x.targets.elevator_target, y.targets.elevator_target, 1e-12);
        EXPECT_NEAR(x.targets.aileron_target, y.targets.aileron_target, 1e-15);
        // Bearing triggers: -180 and +180 deg are the same crossing (the trigger wraps differences).
        const bool angle = x.trigger.kind == guidance::TriggerKind::bearing;
        EXPECT_NEAR(angle ? math::wrap_pi(x.trigger.value - y.trigger.value) : x.trigger.value - y.trigger.value, 0.0,
                    1e-12);
    }
}

}  // namespace

TEST(PaperScenario, PureFunctionOfSeedAndRun) {
    const auto a = generate_paper_scenario(1, tmpl(), 3, 7, "t");
    const auto b = generate_paper_scenario(1, tmpl(), 3, 7, "t");
    const auto c = generate_paper_scenario(1, tmpl(), 3, 8, "t");
    const auto d = generate_paper_scenario(1, tmpl(), 4, 7, "t");
    EXPECT_EQ(text(a.doc), text(b.doc));
    EXPECT_NE(text(a.doc), text(c.doc));
    EXPECT_NE(text(a.doc), text(d.doc));
    EXPECT_FALSE(a.doc["generator"]);
}

TEST(PaperScenario, EachPartFromItsOwnStream) {
    const auto g = generate_paper_scenario(1, tmpl(), 3, 7, "t");
    rnd::Stream m = rnd::Stream::derive(3, 7, "scenario/mission");
    rnd::Stream w = rnd::Stream::derive(3, 7, "scenario/wind");
    rnd::Stream o = rnd::Stream::derive(3, 7, "scenario/offsets");
    rnd::Stream e = rnd::Stream::derive(3, 7, "scenario/earth");
    const auto dm = guidance::draw_scenario1(m, 100.0);
    const auto dw = physics::draw_wind_scenario(w, true);
    const auto dof = atm::draw_offsets_scenario(o, true);
    const auto de = earth::draw_earth_truth(e);
    EXPECT_EQ(g.draws.mission.common.airspeed_ini_mps, dm.airspeed_ini_mps);
    EXPECT_EQ(g.draws.mission.common.turn_time_s, dm.turn_time_s);
    EXPECT_EQ(g.draws.wind.speed_end_mps, dw.speed_end_mps);
    EXPECT_EQ(g.draws.offsets.dp_end_Pa, dof.dp_end_Pa);
    EXPECT_EQ(g.draws.earth.mag_dev_n_nT, de.mag_dev_n_nT);
    // The explicit values in the document read back exactly (shortest round-trip text).
    const YAML::Node fp = g.doc["components"]["flight_physics"];
    EXPECT_EQ(num(fp["wind"]["speed_end_mps"]), dw.speed_end_mps);
    EXPECT_EQ(num(fp["offsets"]["dT_end_K"]), dof.dT_end_K);
    EXPECT_EQ(num(fp["earth_truth"]["mag_dev_n_nT"][2]), de.mag_dev_n_nT.z());
    EXPECT_EQ(num(fp["initial"]["tas_mps"]), dm.airspeed_ini_mps);
    EXPECT_EQ(num(fp["initial"]["Hp_m"]), dm.pressure_altitude_ini_m);
    EXPECT_NEAR(num(fp["initial"]["bearing_deg"]), math::rad2deg(dm.bearing_ini_rad), 1e-12);
    EXPECT_EQ(num(g.doc["components"]["gnss"]["loss_time_s"]), 100.0);
    EXPECT_EQ(num(g.doc["components"]["rec"]["t_gnss_s"]), 100.0);
    EXPECT_EQ(fp["initial"]["lat_deg"].as<double>(), 45.0);  // the template's values stay
}

TEST(PaperScenario, BothScenariosShareTheCommonDraws) {
    // As the reference: for one seed both scenarios fly the same chi_0, chi_1, V_ini, Hp_ini, t_turn, initial
    // wind, dT_ini, dp_ini and Earth deviations.
    for (std::uint64_t run = 0; run < 20; ++run) {
        const auto s1 = scenario::draw_paper_scenario(1, 11, run, nullptr);
        const auto s2 = scenario::draw_paper_scenario(2, 11, run, nullptr);
        EXPECT_EQ(s1.mission.common.bearing_ini_rad, s2.mission.common.bearing_ini_rad);
        EXPECT_EQ(s1.mission.common.bearing_end_rad, s2.mission.common.bearing_end_rad);
        EXPECT_EQ(s1.mission.common.airspeed_ini_mps, s2.mission.common.airspeed_ini_mps);
        EXPECT_EQ(s1.mission.common.pressure_altitude_ini_m, s2.mission.common.pressure_altitude_ini_m);
        EXPECT_EQ(s1.mission.common.turn_time_s, s2.mission.common.turn_time_s);
        EXPECT_EQ(s1.wind.speed_ini_mps, s2.wind.speed_ini_mps);
        EXPECT_EQ(s1.offsets.dT_ini_K, s2.offsets.dT_ini_K);
        EXPECT_EQ(s1.offsets.dp_ini_Pa, s2.offsets.dp_ini_Pa);
        EXPECT_EQ(s1.earth.tilt_rad, s2.earth.tilt_rad);
        // Scenario #2: constant wind and offsets; t_end 500 s; scenario #1: 3800 s.
        EXPECT_EQ(s2.wind.speed_end_mps, s2.wind.speed_ini_mps);
        EXPECT_EQ(s2.offsets.dp_end_Pa, s2.offsets.dp_ini_Pa);
        EXPECT_EQ(s1.t_end_s, 3800.0);
        EXPECT_EQ(s2.t_end_s, 500.0);
        EXPECT_EQ(s1.t_gnss_s, 100.0);
    }
}

TEST(PaperScenario, InlineMissionIsTheScenarioMission) {
    for (int sc : {1, 2})
        for (std::uint64_t run = 0; run < 10; ++run) {
            const auto g = generate_paper_scenario(sc, tmpl(), 5, run, "t");
            const YAML::Node mission = g.doc["components"]["guidance"]["mission"];
            const guidance::Mission parsed = guidance::parse_mission(config::Config::wrap(mission, "t"));
            expect_same_operations(parsed, scenario::paper_mission(g.draws));
            EXPECT_EQ(parsed.operations.size(), sc == 1 ? 6u : 17u);
        }
}

TEST(PaperScenario, FileValuesOverrideDrawsKeyByKey) {
    const auto g = generate_paper_scenario(1, tmpl(), 3, 7, "t");
    YAML::Node t = tmpl();
    t["components"]["flight_physics"]["wind"] = YAML::Load("{speed_ini_mps: 0, speed_end_mps: 0}");
    t["components"]["gnss"]["loss_time_s"] = 250;
    const auto o = generate_paper_scenario(1, t, 3, 7, "t");
    const YAML::Node w = o.doc["components"]["flight_physics"]["wind"];
    EXPECT_EQ(num(w["speed_ini_mps"]), 0.0);
    EXPECT_EQ(num(w["speed_end_mps"]), 0.0);
    EXPECT_EQ(num(w["t_ini_s"]), g.draws.wind.t_ini_s);  // the rest is still drawn
    EXPECT_EQ(num(o.doc["components"]["gnss"]["loss_time_s"]), 250.0);
    EXPECT_EQ(std::count(o.kept.begin(), o.kept.end(), "components.flight_physics.wind.speed_ini_mps"), 1);
    EXPECT_EQ(std::count(o.kept.begin(), o.kept.end(), "components.gnss.loss_time_s"), 1);
    // Other parts are unchanged by the override (independent streams).
    EXPECT_EQ(text(o.doc["components"]["guidance"]), text(g.doc["components"]["guidance"]));
}

TEST(PaperScenario, GivenMissionIsKeptAndNoInitialFlightIsWritten) {
    YAML::Node t = tmpl();
    t["components"]["guidance"]["mission"] = "missions/scenario1_example.yaml";
    const auto g = generate_paper_scenario(1, t, 3, 7, "t");
    EXPECT_EQ(g.doc["components"]["guidance"]["mission"].as<std::string>(), "missions/scenario1_example.yaml");
    EXPECT_FALSE(g.doc["components"]["flight_physics"]["initial"]["tas_mps"]);
}

TEST(PaperScenario, GeneratorOptionsFixDraws) {
    const auto g = generate_paper_scenario(2, tmpl(), 3, 7, "t");
    YAML::Node t = tmpl();
    t["generator"] = YAML::Load(
        "{name: paper_scenario2, t_gnss_s: 60, t_end_s: 300, fixed: {airspeed_ini_mps: 30, Hp_ini_m: 1500, "
        "legs_s: [10, 10, 10, 10, 10, 10, 10]}}");
    const auto f = generate_paper_scenario(2, t, 3, 7, "t");
    EXPECT_EQ(f.draws.mission.common.airspeed_ini_mps, 30.0);
    EXPECT_EQ(f.draws.mission.common.pressure_altitude_ini_m, 1500.0);
    EXPECT_EQ(f.draws.mission.leg_s[6], 10.0);
    EXPECT_EQ(f.draws.mission.bearing_rad, g.draws.mission.bearing_rad);  // not fixed: the same draw
    EXPECT_EQ(f.draws.t_end_s, 300.0);
    EXPECT_EQ(num(f.doc["components"]["gnss"]["loss_time_s"]), 60.0);
    EXPECT_EQ(num(f.doc["components"]["flight_physics"]["initial"]["tas_mps"]), 30.0);
    // t_gnss changes the drawn turn time (t_turn = t_GNSS + 30 + 50 N, >= t_GNSS + 15).
    EXPECT_GE(f.draws.mission.common.turn_time_s, 75.0);
}

TEST(PaperScenario, BadGeneratorOptionsNameTheKey) {
    YAML::Node t = tmpl();
    t["generator"] = YAML::Load("{name: paper_scenario1, t_gnss: 100}");
    try {
        (void)generate_paper_scenario(1, t, 1, 0, "paper1.yaml");
        FAIL() << "no error";
    } catch (const config::ConfigError& e) {
        EXPECT_NE(std::string(e.what()).find("t_gnss"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("paper1.yaml"), std::string::npos) << e.what();
    }
    t["generator"] = YAML::Load("{name: paper_scenario1, fixed: {airspeed_ini_mps: 90}}");
    EXPECT_THROW((void)generate_paper_scenario(1, t, 1, 0, "t"), config::ConfigError);
}

TEST(PaperScenario, DrawsStayInsideTheComponentRanges) {
    // 200 runs of each scenario: the explicit values respect the scenario definitions
    // (docs/montecarlo.md, "Scenarios #1 and #2"), and so the physics ranges.
    for (int sc : {1, 2})
        for (std::uint64_t run = 0; run < 200; ++run) {
            const auto d = scenario::draw_paper_scenario(sc, 1, run, nullptr);
            const auto& c = d.mission.common;
            EXPECT_GE(c.airspeed_ini_mps, 24.0);
            EXPECT_LE(c.airspeed_ini_mps, 34.0);
            EXPECT_GE(c.turn_time_s, 115.0);
            EXPECT_GE(std::fabs(c.pressure_altitude_end_m - c.pressure_altitude_ini_m), 100.0);
            EXPECT_GE(d.wind.speed_ini_mps, 0.0);
            EXPECT_GE(d.wind.t_end_s, d.wind.t_ini_s + 300.0 - 1e-9);
        }
}

TEST(PaperScenario, RegisteredAsGenerators) {
    scenario::register_paper_scenarios();
    ASSERT_NE(framework::find_scenario_generator("paper_scenario1"), nullptr);
    ASSERT_NE(framework::find_scenario_generator("paper_scenario2"), nullptr);
    const YAML::Node doc = (*framework::find_scenario_generator("paper_scenario2"))(tmpl(), 3, 7, "t");
    EXPECT_EQ(doc["components"]["guidance"]["mission"]["operations"].size(), 9u);  // hold + 8 turns (file format)
}

TEST(ScenarioYaml, ShortestRoundTripNumbersAndIntegerDegrees) {
    EXPECT_EQ(scenario::shortest(29.13), "29.13");
    EXPECT_EQ(scenario::shortest(-72.0), "-72");
    EXPECT_EQ(scenario::shortest(0.1 + 0.2), "0.30000000000000004");
    EXPECT_EQ(scenario::degrees(math::deg2rad(-56.0)).as<std::string>(), "-56");
    EXPECT_EQ(scenario::degrees(0.5).as<double>(), math::rad2deg(0.5));
}
