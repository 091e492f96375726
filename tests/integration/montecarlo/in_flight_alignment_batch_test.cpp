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
    print_and_check_runs(al, tf, "in-flight");
    EXPECT_LE(tf.hor_mean, 1.1 * al.hor_mean);
    EXPECT_LE(tf.att_mean, 1.1 * al.att_mean);
}
