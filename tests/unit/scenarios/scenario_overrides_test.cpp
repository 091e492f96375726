// Command-line overrides of scenario files: --set, --grade, --variant.
#include <gtest/gtest.h>

#include <algorithm>

#include "config/config.hpp"
#include "framework/run_config.hpp"
#include "scenario_overrides.hpp"
#include "scenario_yaml.hpp"

using namespace gdnav;
using config::ConfigError;

namespace {

YAML::Node doc() {
    return YAML::Load(R"(
run: {seed: 1, duration_s: 10}
components:
  imu: {type: sensors_inertial, suite: sensors/suite.yaml}
  mag: {type: sensors_magnetic, suite: sensors/suite.yaml}
  air: {type: sensors_air, suite: sensors/suite.yaml}
  atm: {type: sensors_atmospheric, suite: sensors/suite.yaml}
  gps: {type: sensors_gnss, suite: sensors/suite.yaml}
  att: {type: nav_att, variant: nav/variants/baseline.yaml}
  pos: {type: nav_pos, variant: nav/variants/baseline.yaml}
  guidance: {type: guidance, mission: {operations: [{op: hold}, {op: turn}]}}
)");
}

}  // namespace

TEST(ApplySet, SetsCreatesAndRemovesKeys) {
    YAML::Node d = doc();
    scenario::apply_set(d, "run.seed=42");
    scenario::apply_set(d, "components.imu.bias_drift_band=300");
    scenario::apply_set(d, "components.new.type=recorder");
    scenario::apply_set(d, "generator.fixed.airspeed_ini_mps=30");
    scenario::apply_set(d, "components.att.tuning={a: 1, b: [2, 3]}");
    scenario::apply_set(d, "run.duration_s=~");
    scenario::apply_set(d, "components.guidance.mission.operations.1.op=hold");
    EXPECT_EQ(d["run"]["seed"].as<int>(), 42);
    EXPECT_EQ(d["components"]["imu"]["bias_drift_band"].as<int>(), 300);
    EXPECT_EQ(d["components"]["new"]["type"].as<std::string>(), "recorder");
    EXPECT_EQ(d["generator"]["fixed"]["airspeed_ini_mps"].as<double>(), 30.0);
    EXPECT_EQ(d["components"]["att"]["tuning"]["b"][1].as<int>(), 3);
    EXPECT_FALSE(d["run"]["duration_s"]);
    EXPECT_EQ(d["components"]["guidance"]["mission"]["operations"][1]["op"].as<std::string>(), "hold");
}

TEST(ApplySet, MalformedAssignmentsAreConfigErrors) {
    YAML::Node d = doc();
    EXPECT_THROW(scenario::apply_set(d, "run.seed"), ConfigError);
    EXPECT_THROW(scenario::apply_set(d, "=3"), ConfigError);
    EXPECT_THROW(scenario::apply_set(d, "run..seed=3"), ConfigError);
    EXPECT_THROW(scenario::apply_set(d, "run.seed.x=3"), ConfigError);  // seed is a number, not a mapping
    EXPECT_THROW(scenario::apply_set(d, "components.guidance.mission.operations.5.op=hold"), ConfigError);
    EXPECT_THROW(scenario::apply_set(d, "run.seed=[1, 2"), ConfigError);
}

TEST(Overrides, GradeForEveryGroupThatHasIt) {
    YAML::Node d = doc();
    scenario::Overrides o;
    o.grades = {"worse"};  // gyroscopes, accelerometers, magnetometers, air_data, atmospheric have it; gnss not
    const auto notes = scenario::apply_overrides(d, o, framework::config_dir());
    EXPECT_EQ(d["components"]["imu"]["gyr_grade"].as<std::string>(), "worse");
    EXPECT_EQ(d["components"]["imu"]["acc_grade"].as<std::string>(), "worse");
    EXPECT_EQ(d["components"]["mag"]["grade"].as<std::string>(), "worse");
    EXPECT_EQ(d["components"]["air"]["grade"].as<std::string>(), "worse");
    EXPECT_EQ(d["components"]["atm"]["grade"].as<std::string>(), "worse");
    EXPECT_FALSE(d["components"]["gps"]["grade"]);
    ASSERT_EQ(notes.size(), 1u);
    EXPECT_NE(notes[0].find("gnss"), std::string::npos);
}

TEST(Overrides, GradeForOneGroupAndErrors) {
    YAML::Node d = doc();
    scenario::Overrides o;
    o.grades = {"gyroscopes=worst"};
    (void)scenario::apply_overrides(d, o, framework::config_dir());
    EXPECT_EQ(d["components"]["imu"]["gyr_grade"].as<std::string>(), "worst");
    EXPECT_FALSE(d["components"]["imu"]["acc_grade"]);
    o.grades = {"magnetometers=worst"};  // magnetometers: baseline, better, worse
    EXPECT_THROW((void)scenario::apply_overrides(d, o, framework::config_dir()), ConfigError);
    o.grades = {"lidar=better"};
    EXPECT_THROW((void)scenario::apply_overrides(d, o, framework::config_dir()), ConfigError);
    o.grades = {"no_such_grade"};
    EXPECT_THROW((void)scenario::apply_overrides(d, o, framework::config_dir()), ConfigError);
}

TEST(Overrides, VariantAndSetOrder) {
    YAML::Node d = doc();
    scenario::Overrides o;
    o.variants = {"hor_double_integration"};
    o.sets = {"components.pos.variant=nav/variants/baseline.yaml"};  // --set is applied last and wins
    (void)scenario::apply_overrides(d, o, framework::config_dir());
    EXPECT_EQ(d["components"]["att"]["variant"].as<std::string>(), "nav/variants/hor_double_integration.yaml");
    EXPECT_EQ(d["components"]["pos"]["variant"].as<std::string>(), "nav/variants/baseline.yaml");
    o = {};
    o.variants = {"att=att_zero_fb_derivatives"};
    (void)scenario::apply_overrides(d, o, framework::config_dir());
    EXPECT_EQ(d["components"]["att"]["variant"].as<std::string>(), "nav/variants/att_zero_fb_derivatives.yaml");
    o.variants = {"nonexistent"};
    EXPECT_THROW((void)scenario::apply_overrides(d, o, framework::config_dir()), ConfigError);
    o.variants = {"nobody=baseline"};
    EXPECT_THROW((void)scenario::apply_overrides(d, o, framework::config_dir()), ConfigError);
}

TEST(Overrides, Aliases) {
    EXPECT_EQ(scenario::scenario_alias("1"), "paper1");
    EXPECT_EQ(scenario::scenario_alias("2"), "paper2");
    EXPECT_EQ(scenario::scenario_alias("paper1_truth"), "paper1_truth");
}
