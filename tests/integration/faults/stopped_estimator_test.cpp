// An estimator killed mid-run (docs/faults.md, "Results of a run whose estimator stopped"): metrics.yaml keeps
// `complete: true` (the run ended normally), adds `estimates_complete: false` and the time of each estimate's last
// step, and its final figures are those of the kill time, divided by the distance flown up to then; the same in the
// direct and the composed layout (DDS, its own domain).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <regex>

#include <yaml-cpp/yaml.h>

#include "h5_column.hpp"
#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

// 16 001 steps from t0 = -50 s: t = 110 s at the end, 10 s past the GNSS loss at t = 100 s. nav_pos dies at the
// step of t = 105.01 s, so its last estimate is that of t = 105.00 s, a recorded row of run.h5 (every 10th step).
const std::string kSteps = "16001";
const std::string kKill = "faults=[{at_s: 105.01, target: nav_pos, kind: kill}]";
constexpr int kDomain = 230;  // this test's own DDS domain (integration tests run one at a time)

fs::path run_killed(const std::string& tag, const std::string& layout) {
    const fs::path out = temp_dir(tag);
    std::vector<std::string> argv{GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--steps", kSteps,
                                  "--layout", layout, "--set", kKill, "--out", out.string()};
    if (layout != "direct") argv.insert(argv.end(), {"--domain", std::to_string(kDomain)});
    const Result r = run(argv, 240.0);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    // The run's last line of navigation results names the stop, the time and the distance flown up to it.
    EXPECT_TRUE(std::regex_search(r.output, std::regex("ESTIMATES INCOMPLETE; final at t = 105\\.00 s \\(last step with "
                                                       "every estimate; stopped: position\\) horizontal error .* m "
                                                       "flown since t_GNSS up to then")))
        << r.output;
    return out;
}

}  // namespace

TEST(StoppedEstimator, NavPosKilledGivesTheFinalFigureAtTheKillTimeAndSaysSo) {
    const fs::path out = run_killed("stopped-direct", "direct");
    const YAML::Node m = YAML::LoadFile((out / "metrics.yaml").string());
    EXPECT_TRUE(m["complete"].as<bool>());  // the run itself ended normally (a batch does not run it again)
    ASSERT_TRUE(m["estimates_complete"]) << read_file(out / "metrics.yaml");
    EXPECT_FALSE(m["estimates_complete"].as<bool>());
    const double t_end = m["t_end_s"].as<double>();
    EXPECT_NEAR(t_end, 105.0, 1e-9);
    EXPECT_NEAR(m["last_estimate_s"]["position"].as<double>(), 105.0, 1e-9);
    EXPECT_NEAR(m["last_estimate_s"]["attitude"].as<double>(), 110.0, 1e-9);
    EXPECT_NEAR(m["last_estimate_s"]["air_data"].as<double>(), 110.0, 1e-9);
    EXPECT_EQ(m["samples"].as<std::uint64_t>(), 10501u);  // t = 0 .. 105 s

    // The row of t = 105.00 s in run.h5: its error is the final error, its distance the one the % divides by.
    const fs::path h5 = out / "run.h5";
    const auto t = h5_column(h5, "error", "t_s");
    const auto hor = h5_column(h5, "error", "hor_m");
    const auto dist = h5_column(h5, "truth", "dist_m");
    ASSERT_EQ(t.size(), 1601u);
    ASSERT_EQ(dist.size(), t.size());
    const std::size_t row = 1550;  // t = -50 + 10 * 0.01 * 1550 = 105 s
    ASSERT_NEAR(t[row], 105.0, 1e-9);
    EXPECT_EQ(m["signals"]["hor_m"]["final"].as<double>(), hor[row]);
    EXPECT_TRUE(std::isnan(hor[row + 1]));  // no position estimate after the kill
    const double d_end = m["distance_at_t_end_m"].as<double>();
    EXPECT_EQ(d_end, dist[row]);
    const double d_all = m["distance_since_gnss_m"].as<double>();
    EXPECT_EQ(d_all, dist.back());
    // 5 s of flight at ~28 m/s after t_GNSS, against 10 s to the end: the old figure divided by twice the distance.
    EXPECT_GT(d_all, 1.8 * d_end);
    EXPECT_EQ(m["final_percent"]["hor"].as<double>(), 100.0 * hor[row] / d_end);
    std::printf("final horizontal error at t = %.2f s (last nav_pos estimate): %.2f m, %.3f %% of %.0f m flown since "
                "t_GNSS (the whole flight's %.0f m would give %.3f %%)\n",
                t_end, hor[row], 100.0 * hor[row] / d_end, d_end, d_all, 100.0 * hor[row] / d_all);

    // Over DDS (composed layout, the kill is the executor's): the same record, byte for byte.
    const fs::path composed = run_killed("stopped-composed", "composed");
    EXPECT_EQ(read_file(composed / "metrics.yaml"), read_file(out / "metrics.yaml"));
    fs::remove_all(out);
    fs::remove_all(composed);
}
