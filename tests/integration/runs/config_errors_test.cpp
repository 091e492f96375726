// Malformed configs: non-zero exit, one clear error line naming file and key, and nothing started.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include <yaml-cpp/yaml.h>

#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

struct Case {
    const char* name;
    std::string yaml;          // empty: the file does not exist
    const char* must_contain;  // part of the error line
};

std::string chain_with(const std::string& run_extra, const std::string& plant) {
    return "run:\n  seed: 1\n  steps: 100\n" + run_extra +
           "components:\n"
           "  chain_plant: " + plant + "\n"
           "  chain_sensor: {type: chain_sensor, sigma_m: 0.1}\n"
           "  chain_filter: {type: chain_filter, alpha: 0.2, beta: 0.02}\n"
           "  chain_controller: {type: chain_controller, kp: 1.0, kd: 1.5, target_m: 0.0}\n";
}
const std::string kPlant = "{type: chain_plant, sigma_w_mps2: 0.5, damping_per_s: 0.2, x0_m: 3.0}";

}  // namespace

TEST(ConfigErrors, EachMalformedConfigGivesOneErrorAndStartsNothing) {
    const std::vector<Case> cases{
        {"missing file", "", "cannot open file"},
        {"malformed yaml", "run: {seed: 1\ncomponents: [", "malformed YAML"},
        {"unknown key", chain_with("  sede: 3\n", kPlant), "key 'run.sede': unknown key"},
        {"wrong type", chain_with("", "{type: chain_plant, sigma_w_mps2: abc, damping_per_s: 0.2, x0_m: 3.0}"),
         "key 'components.chain_plant.sigma_w_mps2': must be a number"},
        {"out of range", chain_with("", "{type: chain_plant, sigma_w_mps2: -0.5, damping_per_s: 0.2, x0_m: 3.0}"),
         "outside allowed range [0, inf)"},
        {"missing key", chain_with("", "{type: chain_plant, sigma_w_mps2: 0.5, x0_m: 3.0}"),
         "key 'components.chain_plant.damping_per_s': missing"},
        {"unknown component type", chain_with("", "{type: chain_plantt}"), "unknown component type 'chain_plantt'"},
        {"out-of-range run value", chain_with("  member_timeout_s: 0\n", kPlant), "key 'run.member_timeout_s'"},
        {"unknown recorder topic",
         chain_with("", kPlant) + "  recorder: {type: recorder, topics: [chain/nope]}\n", "unknown topic 'chain/nope'"},
    };
    for (const auto& c : cases) {
        const auto dir = temp_dir("cfg");
        const fs::path file = dir / "scenario.yaml";
        if (!c.yaml.empty()) std::ofstream(file) << c.yaml;
        const auto out = dir / "out";
        const Result r = run({testchain_exe(), "run", "--scenario", file.string(), "--layout", "distributed", "--out",
                              out.string()},
                             30.0);
        SCOPED_TRACE(c.name);
        EXPECT_NE(r.exit_code, 0) << r.output;
        // Exactly one line of output: the error.
        std::size_t lines = 0;
        for (char ch : r.output) lines += (ch == '\n');
        EXPECT_EQ(lines, 1u) << r.output;
        EXPECT_NE(r.output.find("error"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(c.must_contain), std::string::npos) << r.output;
        if (!c.yaml.empty()) {
            EXPECT_NE(r.output.find(file.string()), std::string::npos) << r.output;
        }
        // Nothing started: no process table, no resolved config.
        EXPECT_FALSE(fs::exists(out / "processes.yaml"));
        EXPECT_FALSE(fs::exists(out / "run.yaml"));
    }
}

// gdnav run takes the same scenario overrides as gdnav scenario/montecarlo (--set, --variant, --grade): a bad override
// is a configuration error before anything starts; good ones end up in the resolved run.yaml.
TEST(ConfigErrors, RunOverridesAreValidatedAndApplied) {
    const auto dir = temp_dir("cfg_overrides");
    {
        const Result r = run({GDNAV_GDNAV_EXE, "run", "--scenario", "2", "--layout", "direct", "--steps", "10",
                              "--set", "run.dt_s=-1", "--out", (dir / "bad").string()},
                             30.0);
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_NE(r.output.find("key 'run.dt_s': value -1 outside allowed range"), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(dir / "bad" / "run.yaml"));
    }
    {
        const Result r = run({GDNAV_GDNAV_EXE, "run", "--scenario", "2", "--layout", "direct", "--steps", "10",
                              "--variant", "no_such_variant", "--out", (dir / "bad2").string()},
                             30.0);
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_NE(r.output.find("no_such_variant"), std::string::npos) << r.output;
    }
    {
        const auto out = dir / "good";
        const Result r = run({GDNAV_GDNAV_EXE, "run", "--scenario", "2", "--layout", "direct", "--steps", "10",
                              "--variant", "hor_double_integration", "--grade", "gyroscopes=worse", "--set",
                              "components.flight_physics.wind.speed_end_mps=0", "--out", out.string()},
                             60.0);
        ASSERT_EQ(r.exit_code, 0) << r.output;
        const YAML::Node doc = YAML::LoadFile((out / "run.yaml").string());
        EXPECT_EQ(doc["components"]["nav_pos"]["variant"].as<std::string>(), "nav/variants/hor_double_integration.yaml");
        EXPECT_EQ(doc["components"]["sensors_inertial"]["gyr_grade"].as<std::string>(), "worse");
        EXPECT_EQ(doc["components"]["flight_physics"]["wind"]["speed_end_mps"].as<double>(), 0.0);
    }
}

// Usage errors are bad input like any other: one line and exit code 2 (not CLI11's own 105, 106 or 109).
TEST(ConfigErrors, UsageErrorsExitTwoWithOneLine) {
    const std::vector<std::vector<std::string>> cases{
        {GDNAV_GDNAV_EXE, "run", "--layout", "bogus"},
        {GDNAV_GDNAV_EXE, "run", "an_extra_argument"},
        {GDNAV_GDNAV_EXE, "validate"},
        // No run's step is shorter than 1e-4 s (run.dt_s): a shorter fault duration is refused before any DDS.
        {GDNAV_GDNAV_EXE, "fault", "--domain", "10", "--target", "nav_att", "--kind", "drop", "--for", "1e-6"},
        {GDNAV_GDNAV_EXE},
    };
    for (const auto& argv : cases) {
        const Result r = run(argv, 30.0);
        SCOPED_TRACE(argv.size() > 1 ? argv[1] : "no subcommand");
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
        EXPECT_NE(r.output.find("error"), std::string::npos) << r.output;
    }
    EXPECT_EQ(run({GDNAV_GDNAV_EXE, "run", "--help"}, 30.0).exit_code, 0);
}

// An external member that never joins: the run's last line states the clock's reason and the exit code; the
// members' copies of the abort are not errors (debug level).
TEST(ConfigErrors, AbsentExternalMemberIsTheCauseOnTheLastLine) {
    const auto dir = temp_dir("absent_external");
    constexpr const char* kDomain = "10";  // of this test alone (integration tests run one at a time)
    const Result r = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--layout", "distributed", "--domain", kDomain,
                          "--steps", "200", "--set", "run.external=[nav_att]", "--set", "run.join_timeout_s=2", "--out",
                          (dir / "out").string()},
                         90.0);
    EXPECT_EQ(r.exit_code, 5) << r.output;
    std::string last = r.output.substr(0, r.output.find_last_not_of('\n') + 1);
    last = last.substr(last.rfind('\n') + 1);
    EXPECT_NE(last.find("run failed (exit code 5): external member 'nav_att' did not join within 2 s (DDS domain 10"),
              std::string::npos)
        << r.output;
    std::size_t errors = 0;
    for (std::size_t p = r.output.find("error:"); p != std::string::npos; p = r.output.find("error:", p + 1)) ++errors;
    EXPECT_EQ(errors, 2u) << r.output;  // the clock's own line and the last line
}
