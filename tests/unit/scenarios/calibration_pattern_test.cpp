// The calibration pattern option of the paper scenario generators: what it adds, and that it changes no draw.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "config/config.hpp"
#include "earth/wgs84.hpp"
#include "framework/scenario_generator.hpp"
#include "gnc/mission_yaml.hpp"
#include "paper_scenarios.hpp"

using namespace gdnav;
using scenario::generate_paper_scenario;

namespace {

YAML::Node tmpl(int sc, const std::string& calibration) {
    std::string gen = "{name: paper_scenario" + std::to_string(sc);
    if (!calibration.empty()) gen += ", calibration: " + calibration;
    gen += "}";
    return YAML::Load("generator: " + gen + R"(
run: {seed: 3, t0_s: -50, duration_s: 550}
components:
  flight_physics: {type: flight_physics, initial: {lat_deg: 45, lon_deg: -90, mass_kg: 19.5}}
  gnss: {type: sensors_gnss, suite: sensors/suite.yaml}
  guidance: {type: guidance}
  rec: {type: nav_recorder}
)");
}

std::string text(const YAML::Node& n) {
    YAML::Emitter e;
    e << n;
    return e.c_str();
}

std::string error_of(int sc, const std::string& calibration) {
    try {
        (void)generate_paper_scenario(sc, tmpl(sc, calibration), 1, 0, "paper2_calibrated.yaml");
    } catch (const config::ConfigError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(CalibrationPattern, ChangesNoDrawAndPrependsThePattern) {
    for (int sc : {1, 2})
        for (const char* cal : {"{pattern: turns, bank_deg: 20}", "{pattern: s_turns, bank_deg: 15, cycles: 3}"}) {
            SCOPED_TRACE(std::to_string(sc) + cal);
            const auto a = generate_paper_scenario(sc, tmpl(sc, ""), 3, 7, "t");
            const auto b = generate_paper_scenario(sc, tmpl(sc, cal), 3, 7, "t");
            // Every section the draws write is the same (wind, offsets, Earth, initial flight, loss time).
            for (const char* c : {"flight_physics", "gnss", "rec"})
                EXPECT_EQ(text(a.doc["components"][c]), text(b.doc["components"][c])) << c;
            // The drawn mission follows the pattern unchanged.
            const YAML::Node oa = a.doc["components"]["guidance"]["mission"]["operations"];
            const YAML::Node ob = b.doc["components"]["guidance"]["mission"]["operations"];
            ASSERT_GT(ob.size(), oa.size());
            const std::size_t n = ob.size() - oa.size();
            for (std::size_t i = 0; i < oa.size(); ++i) EXPECT_EQ(text(oa[i]), text(ob[n + i])) << i;
            // The run starts earlier by a whole number of seconds and keeps its end.
            const double dt0 = a.doc["run"]["t0_s"].as<double>() - b.doc["run"]["t0_s"].as<double>();
            EXPECT_GT(dt0, 0.0);
            EXPECT_EQ(dt0, std::floor(dt0));
            EXPECT_EQ(b.doc["run"]["duration_s"].as<double>(), a.doc["run"]["duration_s"].as<double>() + dt0);
            // The calibrated mission is a valid mission.
            const guidance::Mission m =
                guidance::parse_mission(config::Config::wrap(b.doc["components"]["guidance"]["mission"], "t"));
            EXPECT_EQ(m.operations.size(), ob.size() + (sc == 1 ? 2u : 8u));  // each turn is 2 operations
        }
}

TEST(CalibrationPattern, TurnsAreTwoFullTurnsAndSTurnsEndOnTheBearing) {
    const auto g = generate_paper_scenario(2, tmpl(2, "{pattern: turns, bank_deg: 20, lead_in_s: 10, settle_s: 5}"),
                                           3, 7, "t");
    const double v = g.draws.mission.common.airspeed_ini_mps;
    const double w = earth::kG0_mps2 * std::tan(math::deg2rad(20.0)) / v;  // coordinated-turn rate
    const YAML::Node ops = g.doc["components"]["guidance"]["mission"]["operations"];
    EXPECT_EQ(ops[1]["aileron"]["bank_deg"].as<double>(), 20.0);
    EXPECT_EQ(ops[2]["aileron"]["bank_deg"].as<double>(), -20.0);
    for (int i : {1, 2}) EXPECT_NEAR(ops[i]["until"]["dt_s"].as<double>() * w, 2.0 * math::kPi, 1e-12);
    const double d = -50.0 - g.doc["run"]["t0_s"].as<double>();
    EXPECT_EQ(d, std::ceil(10.0 + 2.0 * 2.0 * math::kPi / w + 5.0));

    const auto s = generate_paper_scenario(2, tmpl(2, "{pattern: s_turns, bank_deg: 20, cycles: 2, amplitude_deg: 60}"),
                                           3, 7, "t");
    const YAML::Node so = s.doc["components"]["guidance"]["mission"]["operations"];
    double heading = 0.0, swing = 0.0;
    for (std::size_t i = 1; i <= 6; ++i) {
        heading += (so[i]["aileron"]["bank_deg"].as<double>() > 0 ? w : -w) * so[i]["until"]["dt_s"].as<double>();
        swing = std::max(swing, std::fabs(heading));
    }
    EXPECT_NEAR(heading, 0.0, 1e-12);
    EXPECT_NEAR(swing, math::deg2rad(60.0), 1e-12);
}

TEST(CalibrationPattern, BadOptionsNameFileKeyAndRange) {
    std::string e = error_of(2, "{pattern: turns, bank_deg: 45}");
    EXPECT_NE(e.find("paper2_calibrated.yaml"), std::string::npos) << e;
    EXPECT_NE(e.find("calibration.bank_deg"), std::string::npos) << e;
    EXPECT_NE(e.find("30"), std::string::npos) << e;
    e = error_of(1, "{pattern: loops, bank_deg: 20}");
    EXPECT_NE(e.find("s_turns"), std::string::npos) << e;
    e = error_of(2, "{pattern: turns}");
    EXPECT_NE(e.find("bank_deg"), std::string::npos) << e;
    e = error_of(2, "{pattern: turns, bank_deg: 20, cycles: 2}");  // cycles belongs to s_turns
    EXPECT_NE(e.find("cycles"), std::string::npos) << e;
    e = error_of(2, "{pattern: s_turns, bank_deg: 20, amplitude_deg: 300}");
    EXPECT_NE(e.find("amplitude_deg"), std::string::npos) << e;
    EXPECT_EQ(error_of(2, "{pattern: s_turns, bank_deg: 20}"), "");
}

TEST(CalibrationPattern, DrawnScenarioOfABatchRunKeepsTheMovedStart) {
    // What gdnav montecarlo writes as each run's drawn_scenario.yaml: with the pattern, the generator moves the run's
    // start, so it needs the run's timing; without it, the drawn text has no timing keys (as before the pattern).
    scenario::register_paper_scenarios();
    const YAML::Node with = framework::drawn_scenario(tmpl(2, "{pattern: turns, bank_deg: 20}"), 3, 1, "t");
    ASSERT_TRUE(with["run"]["t0_s"]);
    EXPECT_LT(with["run"]["t0_s"].as<double>(), -50.0 - 60.0);  // two full turns at 20 deg of bank take minutes
    EXPECT_GT(with["run"]["duration_s"].as<double>(), 550.0 + 60.0);
    const YAML::Node without = framework::drawn_scenario(tmpl(2, ""), 3, 1, "t");
    EXPECT_FALSE(without["run"]["t0_s"]);
    EXPECT_FALSE(without["run"]["duration_s"]);
    EXPECT_TRUE(without["components"]["guidance"]["mission"]);
}
