// Grade and suite configuration: the grade files hold the paper's table values, switching one grade changes
// exactly the parameters of that table, and bad files fail with a ConfigError naming file and key.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

#include <unistd.h>

#include "sensor_test_support.hpp"

namespace gdnav::sensors {
namespace {

namespace fs = std::filesystem;
using config::Config;
using config::ConfigError;
using Params = std::map<std::string, double>;

constexpr double kDeg = math::kDeg;

Params as_map(const SensorSuiteParams& s) {
    Params m;
    for (const auto& [k, v] : list_parameters(s)) m[k] = v;
    return m;
}

// The suite file with one group's grade replaced (keeps the real grade files).
SensorSuiteParams suite_with(const std::string& group, const std::string& grade) {
    std::string text = "sample_period_s: 0.01\nstart_time_s: -50.0\nbias_drift_band: 100\n";
    for (const char* g : {"gyroscopes", "accelerometers", "magnetometers", "air_data", "atmospheric"}) {
        text += std::string(g) + ": {grade: " + (group == g ? grade : std::string("baseline")) + "}\n";
    }
    text += "gnss: {grade: baseline, loss_time_s: 100.0}\n";
    const Config real = Config::load(test::sensors_config_dir() / "suite.yaml");
    YAML::Node node = YAML::Load(text);
    node["platform"] = real.node()["platform"];
    node["alignment"] = real.node()["alignment"];
    return parse_sensor_suite(Config::wrap(node, "suite_with(" + group + ")"), test::sensors_config_dir());
}

// Parameters whose values differ between two suites.
std::set<std::string> changed(const Params& a, const Params& b) {
    std::set<std::string> out;
    for (const auto& [k, v] : a) {
        if (b.at(k) != v) out.insert(k);
    }
    return out;
}

void expect_triad(const Params& m, const std::string& p, double su, double sv, double s, double mm, double b0,
                  double unit) {
    EXPECT_NEAR(m.at(p + ".bias_drift"), su * unit, 1e-12 * unit) << p;
    EXPECT_NEAR(m.at(p + ".system_noise"), sv * unit, 1e-12 * unit) << p;
    EXPECT_NEAR(m.at(p + ".scale_factor"), s, 1e-15) << p;
    EXPECT_NEAR(m.at(p + ".cross_coupling"), mm, 1e-15) << p;
    EXPECT_NEAR(m.at(p + ".bias_offset"), b0 * unit, 1e-12 * unit) << p;
}

const std::set<std::string> kTriad = {".bias_drift", ".system_noise", ".scale_factor", ".cross_coupling",
                                      ".bias_offset"};
std::set<std::string> prefixed(const std::string& p, const std::set<std::string>& names) {
    std::set<std::string> out;
    for (const auto& n : names) out.insert(p + n);
    return out;
}

TEST(SensorConfig, BaselineHoldsThePaperTables) {
    const Params m = as_map(test::baseline_suite());
    // Paper table "Performance of Baseline gyroscopes and accelerometers".
    expect_triad(m, "gyr", 1.42e-4, 4.30e-3, 1.50e-5, 4.35e-5, 2.00e-1, kDeg);
    expect_triad(m, "acc", 6.86e-5, 4.83e-4, 5.00e-5, 3.05e-5, 1.57e-1, 1.0);
    // Paper table "Performance of Baseline magnetometers".
    EXPECT_EQ(m.at("mag.system_noise_nT_rts"), 5.0);
    EXPECT_EQ(m.at("mag.scale_factor"), 7.50e-4);
    EXPECT_EQ(m.at("mag.cross_coupling"), 9.16e-4);
    EXPECT_EQ(m.at("mag.hard_iron_nT"), 175.0);
    EXPECT_EQ(m.at("mag.bias_offset_nT"), 500.0);
    // Paper table "Performance of Baseline airspeed and air data sensors".
    EXPECT_EQ(m.at("air.tas_mps.noise"), 0.333);
    EXPECT_EQ(m.at("air.tas_mps.bias_offset"), 0.333);
    EXPECT_NEAR(m.at("air.aoa_rad.noise"), 0.333 * kDeg, 1e-15);
    EXPECT_NEAR(m.at("air.aos_rad.bias_offset"), 0.333 * kDeg, 1e-15);
    EXPECT_EQ(m.at("atm.p_Pa.noise"), 100.0);
    EXPECT_EQ(m.at("atm.T_K.bias_offset"), 0.05);
    EXPECT_EQ(m.at("inertial.bias_drift_band"), 100.0);
    EXPECT_EQ(m.at("gnss.loss_time_s"), 100.0);
}

TEST(SensorConfig, SwitchingAGradeChangesExactlyThatTable) {
    const Params base = as_map(test::baseline_suite());
    struct Case {
        std::string group, grade;
        std::set<std::string> names;
    };
    const std::set<std::string> scalar = {".noise", ".bias_offset"};
    std::set<std::string> air, atm;
    for (const char* s : {"air.tas_mps", "air.aoa_rad", "air.aos_rad"}) air.merge(prefixed(s, scalar));
    for (const char* s : {"atm.p_Pa", "atm.T_K"}) atm.merge(prefixed(s, scalar));
    const std::set<std::string> mag = {"mag.system_noise_nT_rts", "mag.scale_factor", "mag.cross_coupling",
                                       "mag.hard_iron_nT", "mag.bias_offset_nT"};
    const Case cases[] = {
        {"gyroscopes", "better", prefixed("gyr", kTriad)},  {"gyroscopes", "worse", prefixed("gyr", kTriad)},
        {"gyroscopes", "worst", prefixed("gyr", kTriad)},   {"accelerometers", "better", prefixed("acc", kTriad)},
        {"accelerometers", "worse", prefixed("acc", kTriad)}, {"accelerometers", "worst", prefixed("acc", kTriad)},
        {"magnetometers", "better", mag},                   {"magnetometers", "worse", mag},
        {"air_data", "better", air},                        {"air_data", "worse", air},
        {"atmospheric", "worse", atm},                      {"atmospheric", "worst", atm},
    };
    for (const Case& c : cases) {
        const Params m = as_map(suite_with(c.group, c.grade));
        EXPECT_EQ(changed(base, m), c.names) << c.group << "/" << c.grade;
    }
    // Values of the paper's grade tables (hand-copied from paper.tex).
    expect_triad(as_map(suite_with("gyroscopes", "better")), "gyr", 1.38e-5, 2.50e-3, 5.00e-6, 1.50e-5, 3.00e-2, kDeg);
    expect_triad(as_map(suite_with("gyroscopes", "worse")), "gyr", 5.00e-4, 8.00e-3, 5.00e-5, 1.50e-4, 7.50e-1, kDeg);
    expect_triad(as_map(suite_with("gyroscopes", "worst")), "gyr", 1.50e-3, 2.50e-2, 1.00e-4, 4.50e-4, 1.50, kDeg);
    expect_triad(as_map(suite_with("accelerometers", "better")), "acc", 4.90e-5, 3.30e-4, 1.50e-5, 1.50e-5, 1.96e-2, 1.0);
    expect_triad(as_map(suite_with("accelerometers", "worse")), "acc", 8.50e-5, 5.00e-4, 8.50e-5, 5.00e-5, 4.50e-1, 1.0);
    expect_triad(as_map(suite_with("accelerometers", "worst")), "acc", 1.20e-4, 6.50e-4, 1.40e-4, 9.50e-5, 8.50e-1, 1.0);
    const Params mb = as_map(suite_with("magnetometers", "better"));
    const Params mw = as_map(suite_with("magnetometers", "worse"));
    EXPECT_EQ(mb.at("mag.system_noise_nT_rts"), 3.0);
    EXPECT_EQ(mb.at("mag.cross_coupling"), 7.00e-4);
    EXPECT_EQ(mw.at("mag.hard_iron_nT"), 350.0);
    EXPECT_EQ(mw.at("mag.bias_offset_nT"), 750.0);
    // Air data: paper values where the reference code disagrees (docs/sensors.md, "Grades").
    const Params ab = as_map(suite_with("air_data", "better"));
    const Params aw = as_map(suite_with("air_data", "worse"));
    EXPECT_EQ(ab.at("air.tas_mps.noise"), 0.15);
    EXPECT_NEAR(ab.at("air.aoa_rad.noise"), 0.10 * kDeg, 1e-15);     // code: 0.15 deg
    EXPECT_NEAR(ab.at("air.aos_rad.bias_offset"), 0.10 * kDeg, 1e-15);
    EXPECT_EQ(aw.at("air.tas_mps.bias_offset"), 0.666);              // code: 0.50
    EXPECT_NEAR(aw.at("air.aoa_rad.noise"), 0.666 * kDeg, 1e-15);    // code: 0.50 deg
    const Params tw = as_map(suite_with("atmospheric", "worst"));
    EXPECT_EQ(tw.at("atm.p_Pa.noise"), 300.0);
    EXPECT_EQ(tw.at("atm.T_K.bias_offset"), 0.5);
}

TEST(SensorConfig, BiasDriftBandIsAConfigValue) {
    const Config real = Config::load(test::sensors_config_dir() / "suite.yaml");
    YAML::Node node = YAML::Clone(real.node());
    node["bias_drift_band"] = 1000;
    const Params m = as_map(parse_sensor_suite(Config::wrap(node, "band"), test::sensors_config_dir()));
    EXPECT_EQ(changed(as_map(test::baseline_suite()), m), std::set<std::string>{"inertial.bias_drift_band"});
    EXPECT_EQ(m.at("inertial.bias_drift_band"), 1000.0);
}

// A temporary grades folder holding one gyroscope grade file with the given text.
std::string load_error(const std::string& gyro_text) {
    const fs::path dir = fs::temp_directory_path() / ("gdnav_sensor_cfg_" + std::to_string(::getpid()));
    fs::create_directories(dir / "gyroscopes");
    const fs::path file = dir / "gyroscopes" / "bad.yaml";
    std::ofstream(file) << gyro_text;
    std::string msg;
    try {
        (void)parse_gyro_grade(load_grade_file(dir, "gyroscopes", "bad"));
    } catch (const ConfigError& e) {
        msg = e.what();
    }
    fs::remove_all(dir);
    return msg;
}

const char* kGoodGyro =
    "bias_drift_deg_s1p5: 1.42e-4\nsystem_noise_deg_s0p5: 4.30e-3\nscale_factor: 1.5e-5\n"
    "cross_coupling: 4.35e-5\nbias_offset_deg_s: 0.2\n";

TEST(SensorConfig, GoodTemporaryGradeLoads) { EXPECT_EQ(load_error(kGoodGyro), ""); }

TEST(SensorConfig, NegativeSigmaNamesFileAndKey) {
    std::string text = kGoodGyro;
    text.replace(text.find("4.30e-3"), 7, "-4.30e-3");
    const std::string e = load_error(text);
    EXPECT_NE(e.find("gyroscopes/bad.yaml"), std::string::npos) << e;
    EXPECT_NE(e.find("'system_noise_deg_s0p5'"), std::string::npos) << e;
}

TEST(SensorConfig, MissingKeyNamesFileAndKey) {
    std::string text = kGoodGyro;
    text.erase(text.find("scale_factor"), std::string("scale_factor: 1.5e-5\n").size());
    const std::string e = load_error(text);
    EXPECT_NE(e.find("gyroscopes/bad.yaml"), std::string::npos) << e;
    EXPECT_NE(e.find("'scale_factor'"), std::string::npos) << e;
    EXPECT_NE(e.find("missing"), std::string::npos) << e;
}

TEST(SensorConfig, MisspelledKeyIsRejected) {
    const std::string e = load_error(std::string(kGoodGyro) + "bias_ofset_deg_s: 0.1\n");
    EXPECT_NE(e.find("bias_ofset_deg_s"), std::string::npos) << e;
}

TEST(SensorConfig, UnknownGradeListsTheAvailableOnes) {
    std::string msg;
    try {
        (void)suite_with("magnetometers", "worst");  // the paper has no MAG Worst table
    } catch (const ConfigError& e) {
        msg = e.what();
    }
    EXPECT_NE(msg.find("magnetometers/worst.yaml"), std::string::npos) << msg;
    EXPECT_NE(msg.find("baseline, better, worse"), std::string::npos) << msg;
}

}  // namespace
}  // namespace gdnav::sensors
