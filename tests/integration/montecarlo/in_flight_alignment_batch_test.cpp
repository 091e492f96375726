// The truth-free start with in-flight fine alignment against the aligned start (the sensors' published pre-flight
// alignment) on the same 10 runs of the calibrated scenario #2, seed 1, direct layout, the paper's filter; the larger
// batches are in docs/results.md. Metrics from t = 0 (the paper's window). Every run aligns in flight; no run
// diverges; the mean attitude error and the mean final horizontal error are within 10 % of the aligned start's. Runs
// are bit-reproducible, so the figures are the same on every machine. It prints every run's figures.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <yaml-cpp/yaml.h>

#include "process_util.hpp"

namespace fs = std::filesystem;

namespace {
constexpr int kRuns = 10;
constexpr double kDeg = 180.0 / 3.14159265358979323846;

struct Batch {
    double att_deg[kRuns]{};
    double hor_m[kRuns]{};
    bool aligned[kRuns]{};
    double att_mean{0.0}, hor_mean{0.0};
};

Batch run_batch(const std::string& tag, const std::vector<std::string>& extra) {
    const fs::path dir = gdnav::testing::temp_dir(tag);
    std::vector<std::string> args = {GDNAV_GDNAV_EXE, "montecarlo", "--scenario", "paper2_calibrated", "--runs",
                                     std::to_string(kRuns), "--jobs", "2", "--layout", "direct", "--seed", "1",
                                     "--no-figures", "--no-report", "--out", dir.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const gdnav::testing::Result r = gdnav::testing::run(args, 600.0);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    Batch b;
    for (int i = 0; i < kRuns; ++i) {
        char name[32];
        std::snprintf(name, sizeof(name), "run_%04d", i);
        const YAML::Node m = YAML::LoadFile((dir / "runs" / name / "metrics.yaml").string());
        EXPECT_TRUE(m["complete"].as<bool>()) << i;
        b.att_deg[i] = m["signals"]["rot_rad"]["mean"].as<double>() * kDeg;
        b.hor_m[i] = std::fabs(m["signals"]["hor_m"]["final"].as<double>());
        b.aligned[i] = m["alignment"] && m["alignment"]["aligned"].as<bool>();
        b.att_mean += b.att_deg[i] / kRuns;
        b.hor_mean += b.hor_m[i] / kRuns;
    }
    fs::remove_all(dir);
    return b;
}
}  // namespace

TEST(NavInFlightAlignmentBatch, Scenario2EveryRunAlignsNoneDivergesAndErrorsWithin10PercentOfTheAlignedStart) {
    const Batch al = run_batch("ifa_batch_aligned", {"--set", "components.nav_att.init_mode=alignment", "--set",
                                                     "components.nav_pos.init_mode=alignment", "--set",
                                                     "components.nav_att.in_flight_alignment=~", "--set",
                                                     "components.nav_pos.in_flight_alignment=~"});
    const Batch tf = run_batch("ifa_batch_in_flight", {});
    std::printf("paper2_calibrated, seed 1, runs 0-%d, paper's filter; metrics from t = 0\n", kRuns - 1);
    std::printf("run  attitude mean [deg]: aligned  in-flight | final horizontal [m]: aligned  in-flight\n");
    for (int i = 0; i < kRuns; ++i) {
        std::printf("%3d  %28.3f %10.3f | %28.1f %10.1f\n", i, al.att_deg[i], tf.att_deg[i], al.hor_m[i], tf.hor_m[i]);
        EXPECT_TRUE(tf.aligned[i]) << "run " << i << " never aligned";
        EXPECT_LT(tf.att_deg[i], 1.0) << "run " << i << " diverged";
    }
    std::printf("mean %27.3f %10.3f | %28.1f %10.1f  (ratios %.3f, %.3f)\n", al.att_mean, tf.att_mean, al.hor_mean,
                tf.hor_mean, tf.att_mean / al.att_mean, tf.hor_mean / al.hor_mean);
    EXPECT_LE(tf.hor_mean, 1.1 * al.hor_mean);
    EXPECT_LE(tf.att_mean, 1.1 * al.att_mean);
}
