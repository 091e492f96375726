// Safe flight until aligned (guidance `until_aligned`, docs/navigation.md "Safe flight until aligned"), with a real
// gdnav run of the calibrated scenario #2 (truth-free start): the guidance targets carry no altitude target before
// the navigation declares itself aligned and the mission's own after, the switch happens at the step of the flag,
// each change is logged once; without the option the mission's altitude targets are flown from the first step.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include <yaml-cpp/yaml.h>

#include "gnc/modes.hpp"
#include "process_util.hpp"
#include "record_reader.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;
using gdnav::gnc::ElevatorMode;

namespace {

std::vector<gdnav::msg::GuidanceTargets> fly(const fs::path& out, const std::string& until_aligned, Result& r) {
    r = run({kExe, "run", "--scenario", "paper2_calibrated", "--seed", "1", "--run", "0", "--layout", "direct",
             "--set", "components.guidance.until_aligned=" + until_aligned, "--record", "GuidanceTargets", "--out",
             out.string()},
            120.0);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return read_records<gdnav::msg::GuidanceTargets>(out, "gdnav/GuidanceTargets");
}

}  // namespace

TEST(UntilAligned, AltitudeTargetsWaitForTheAlignedFlagThenTheMissionsOwnAreFlown) {
    const fs::path out = temp_dir("until-aligned");
    Result r;
    const auto targets = fly(out, "true", r);
    ASSERT_FALSE(targets.empty());
    const YAML::Node m = YAML::LoadFile((out / "metrics.yaml").string());
    ASSERT_TRUE(m["alignment"]["aligned"].as<bool>()) << "run 0 of seed 1 aligns (docs/results.md)";
    const double t_aligned = m["alignment"]["t_aligned_s"].as<double>();
    std::size_t before = 0, after = 0;
    for (const auto& g : targets) {
        const auto mode = static_cast<ElevatorMode>(g.elevator_mode());
        if (g.stamp().t_s() < t_aligned - 1e-9) {
            EXPECT_EQ(mode, ElevatorMode::air_path_angle) << "t = " << g.stamp().t_s();
            EXPECT_EQ(g.elevator_target(), 0.0);
            ++before;
        } else {
            EXPECT_EQ(mode, ElevatorMode::pressure_altitude) << "t = " << g.stamp().t_s();  // the mission's mode
            ++after;
        }
    }
    EXPECT_GT(before, 1000u);
    EXPECT_GT(after, 1000u);
    // Each change of mode is logged once, the second at the time of the flag.
    EXPECT_EQ(count_of(r.output, "navigation not aligned: altitude targets flown as air_path_angle 0"), 1u) << r.output;
    EXPECT_EQ(count_of(r.output, "navigation aligned: flying the mission's altitude targets"), 1u) << r.output;
    std::smatch at;
    ASSERT_TRUE(std::regex_search(r.output, at, std::regex("flying the mission's altitude targets from t = (-?[0-9.]+) s")))
        << r.output;
    EXPECT_NEAR(std::stod(at[1]), t_aligned, 0.005);
    std::printf("aligned at t = %.2f s: %zu steps without an altitude target, %zu with the mission's\n", t_aligned,
                before, after);
    fs::remove_all(out);
}

TEST(UntilAligned, WithoutTheOptionTheMissionsAltitudeTargetsAreFlownFromTheFirstStep) {
    const fs::path out = temp_dir("until-aligned-off");
    Result r;
    const auto targets = fly(out, "false", r);
    ASSERT_FALSE(targets.empty());
    for (const auto& g : targets)
        ASSERT_EQ(static_cast<ElevatorMode>(g.elevator_mode()), ElevatorMode::pressure_altitude)
            << "t = " << g.stamp().t_s();
    EXPECT_EQ(r.output.find("navigation not aligned"), std::string::npos) << r.output;
    fs::remove_all(out);
}
