// Issue 14 item 1 acceptance: the truth-free start (init_mode measurements: coarse levelling and magnetic heading
// from the first samples, biases at zero with their sensor-grade sigmas; no pre-flight alignment) against the
// `alignment` start on the same 10 runs of the paper's scenario #2 (`gdnav montecarlo --scenario 2 --runs 10`,
// seed 1, direct layout, error-state attitude filter in both). Metrics from t = 0, i.e. after a 50 s settling time
// from the filters' start at t0 = -50 s. The target: mean attitude error and mean final horizontal error
// within 10 % of the alignment start's. It prints every run's figures.
//
// NOT MET (docs/navigation.md, "Truth-free initialisation"): in the GNSS-aided phase of the paper's missions
// (t = -50 .. 100 s) the aircraft flies straight and level at constant heading, where the accelerometer bias is not
// separable from the tilt, nor the magnetometer bias from the heading; measured 12.5 deg against 0.13 deg. The CTest
// entry is therefore DISABLED; run build/tests/test_integration_nav_truth_free_batch to print the figures.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "metrics/run_record.hpp"
#include "process_util.hpp"

namespace fs = std::filesystem;

namespace {
struct Batch {
    double att_deg[10]{};
    double hor_m[10]{};
    double att_mean{0.0}, hor_mean{0.0};
};

Batch run_batch(const std::string& tag, const std::vector<std::string>& extra) {
    using gdnav::metrics::Signal;
    const fs::path dir = gdnav::testing::temp_dir(tag);
    std::vector<std::string> args = {GDNAV_GDNAV_EXE, "montecarlo", "--scenario", "2",  "--runs",       "10",
                                     "--jobs",        "2",          "--layout",   "direct", "--seed",   "1",
                                     "--no-figures",  "--no-report", "--out",     dir.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const gdnav::testing::Result r = gdnav::testing::run(args, 900.0);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    Batch b;
    for (int i = 0; i < 10; ++i) {
        char name[32];
        std::snprintf(name, sizeof(name), "run_%04d", i);
        const auto rec = gdnav::metrics::read_run_record(dir / "runs" / name / "metrics.yaml");
        EXPECT_TRUE(rec.complete) << i;
        b.att_deg[i] = rec[Signal::rot].mean * 180.0 / std::acos(-1.0);
        b.hor_m[i] = rec[Signal::hor].final;
        b.att_mean += b.att_deg[i] / 10.0;
        b.hor_mean += b.hor_m[i] / 10.0;
    }
    return b;
}
}  // namespace

TEST(NavTruthFreeBatch, Scenario2TruthFreeStartWithin10PercentOfAlignment) {
    const Batch al = run_batch("tf_batch_alignment", {"--variant", "att_error_state"});
    const Batch tf = run_batch("tf_batch_truth_free",
                               {"--variant", "att_error_state", "--set", "components.nav_att.init_mode=measurements",
                                "--set", "components.nav_pos.init_mode=measurements"});
    std::printf("scenario #2, seed 1, runs 0-9, error-state filter; metrics from t = 0 (50 s after the start)\n");
    std::printf("run  attitude mean [deg]: alignment  truth-free | final horizontal [m]: alignment  truth-free\n");
    for (int i = 0; i < 10; ++i)
        std::printf("%3d  %30.3f %11.3f | %30.1f %11.1f\n", i, al.att_deg[i], tf.att_deg[i], al.hor_m[i], tf.hor_m[i]);
    std::printf("mean %29.3f %11.3f | %30.1f %11.1f\n", al.att_mean, tf.att_mean, al.hor_mean, tf.hor_mean);
    EXPECT_LE(tf.att_mean, 1.1 * al.att_mean);
    EXPECT_LE(tf.hor_mean, 1.1 * al.hor_mean);
}
