// The variant keep_gnss_calibration against the aligned start (the paper's filters from the sensors' published
// pre-flight alignment) on the same 20 runs of the calibrated scenario #2, seed 1 (docs/results.md, "Beyond the
// paper"): every run completes and aligns, none diverges, the final horizontal error meets the issue's 135 m target
// and the mean attitude error is at least 10 % below the aligned start's (measured over 100 runs: −15 %; the −33 %
// target is not met, docs/results.md says why). A study (label `study`): `ctest -L study` runs it.
#include <gtest/gtest.h>

#include <cstdio>

#include "batch_metrics.hpp"

using namespace gdnav::testing;

namespace {
constexpr int kRuns = 20;
}  // namespace

TEST(KeepGnssCalibrationBatch, Scenario2CalibratedBeatsTheAlignedStartOn20Runs) {
    const BatchFigures al = run_nav_batch("kgc_batch_aligned", "paper2_calibrated", kRuns, kAlignedStart);
    const BatchFigures kg =
        run_nav_batch("kgc_batch_variant", "paper2_calibrated", kRuns, {"--variant", "keep_gnss_calibration"});
    std::printf("paper2_calibrated, seed 1, runs 0-%d; metrics from t = 0\n", kRuns - 1);
    std::printf("run  attitude mean [deg]: aligned  keep_gnss_calibration | final horizontal [m]: aligned  variant\n");
    for (int i = 0; i < kRuns; ++i) {
        std::printf("%3d  %28.3f %10.3f | %28.1f %10.1f\n", i, al.att_deg[i], kg.att_deg[i], al.hor_m[i], kg.hor_m[i]);
        EXPECT_TRUE(kg.aligned[i]) << "run " << i << " never aligned";
        EXPECT_LT(kg.att_deg[i], 1.0) << "run " << i << " diverged";
    }
    std::printf("mean %27.3f %10.3f | %28.1f %10.1f  (ratios %.3f, %.3f)\n", al.att_mean, kg.att_mean, al.hor_mean,
                kg.hor_mean, kg.att_mean / al.att_mean, kg.hor_mean / al.hor_mean);
    EXPECT_LE(kg.hor_mean, 135.0);
    EXPECT_LE(kg.att_mean, 0.9 * al.att_mean);
}
