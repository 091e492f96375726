// The truth-free start with in-flight fine alignment against the aligned start (the sensors' published pre-flight
// alignment) on the same 10 runs of the calibrated scenario #2, seed 1, direct layout, the paper's filter; the larger
// batches are in docs/results.md. Metrics from t = 0 (the paper's window). Every run aligns in flight; no run
// diverges; the mean attitude error and the mean final horizontal error are within 10 % of the aligned start's. Runs
// are bit-reproducible, so the figures are the same on every machine. It prints every run's figures.
#include <gtest/gtest.h>

#include <cstdio>

#include "batch_metrics.hpp"

using namespace gdnav::testing;

namespace {
constexpr int kRuns = 10;
}  // namespace

TEST(NavInFlightAlignmentBatch, Scenario2EveryRunAlignsNoneDivergesAndErrorsWithin10PercentOfTheAlignedStart) {
    const BatchFigures al = run_nav_batch("ifa_batch_aligned", "paper2_calibrated", kRuns, kAlignedStart);
    const BatchFigures tf = run_nav_batch("ifa_batch_in_flight", "paper2_calibrated", kRuns, {});
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
