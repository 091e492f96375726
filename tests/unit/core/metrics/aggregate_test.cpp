// Aggregation across runs (docs/montecarlo.md, "Aggregation and report") and the paper-layout tables.
#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <limits>

#include "metrics/report_tables.hpp"

using namespace gdnav::metrics;

TEST(Aggregate, MeanPopulationStdSignedMax) {
    const Aggregate a = aggregate({1.0, -3.0, 2.0});
    EXPECT_EQ(a.n, 3u);
    EXPECT_NEAR(a.mean, 0.0, 1e-15);
    EXPECT_NEAR(a.std, std::sqrt(14.0 / 3.0), 1e-14);  // (1 + 9 + 4) / 3
    EXPECT_EQ(a.max, -3.0);
}

TEST(Aggregate, PerRunMaximaUseAbsoluteValuesForMeanAndStd) {
    const Aggregate a = aggregate_abs_max({1.0, -3.0, 2.0});
    EXPECT_NEAR(a.mean, 2.0, 1e-15);                   // |.| = 1, 3, 2
    EXPECT_NEAR(a.std, std::sqrt(2.0 / 3.0), 1e-15);   // (1 + 1 + 0) / 3
    EXPECT_EQ(a.max, -3.0);                            // signed smax of the signed values
}

TEST(Aggregate, NonFiniteValuesAreSkipped) {
    const Aggregate a = aggregate({1.0, std::numeric_limits<double>::quiet_NaN(), 3.0});
    EXPECT_EQ(a.n, 2u);
    EXPECT_NEAR(a.mean, 2.0, 1e-15);
    EXPECT_NEAR(a.std, 1.0, 1e-15);
}

namespace {
RunRecord record(std::uint64_t run, double yaw_mean, double h_final, double hor_final, double distance) {
    RunRecord r;
    r.complete = true;
    r.run_index = run;
    r.distance_m = distance;
    r.signals[gdnav::metrics::index(Signal::yaw)] = {yaw_mean, 0.5 * std::fabs(yaw_mean), -2.0 * yaw_mean, yaw_mean};
    r.signals[gdnav::metrics::index(Signal::h)] = {0.0, 1.0, h_final, h_final};
    r.signals[gdnav::metrics::index(Signal::hor)] = {hor_final / 2, 1.0, hor_final, hor_final};
    r.hor_pct = 100.0 * hor_final / distance;
    return r;
}
}  // namespace

TEST(Aggregate, BatchOfRunsAndPaperTables) {
    constexpr double kDeg = 3.14159265358979323846 / 180.0;
    const std::vector<RunRecord> runs{record(0, 0.010 * kDeg, -4.0, 100.0, 10000.0),
                                      record(1, 0.062 * kDeg, 10.0, 300.0, 12000.0)};
    const BatchAggregate b = aggregate_runs(runs);
    EXPECT_EQ(b.runs, 2u);
    EXPECT_NEAR(b[Signal::yaw].mean.mean / kDeg, 0.036, 1e-12);  // (0.010 + 0.062) / 2
    EXPECT_NEAR(b[Signal::yaw].mean.std / kDeg, 0.026, 1e-12);
    EXPECT_NEAR(b[Signal::yaw].max.mean / kDeg, 0.072, 1e-12);   // mean of |smax| = |-0.020|, |-0.124|
    EXPECT_NEAR(b[Signal::yaw].max.max / kDeg, -0.124, 1e-12);
    EXPECT_NEAR(b[Signal::h].final.mean, 3.0, 1e-12);
    EXPECT_NEAR(b[Signal::h].final.std, 7.0, 1e-12);
    EXPECT_EQ(b[Signal::h].final.max, 10.0);
    EXPECT_NEAR(b.distance.mean, 11000.0, 1e-9);
    EXPECT_NEAR(b.hor_pct.mean, 0.5 * (1.0 + 2.5), 1e-12);  // per-run % first, then aggregated

    const std::string md = paper_tables_markdown({{"#1", b, runs}}, "# test");
    EXPECT_NE(md.find("| #1 | mean | +0.036 | "), std::string::npos) << md;
    EXPECT_NE(md.find("| mean | +3.00 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| std | 7.00 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| max | +10.00 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| #1 | mean | 11000 |"), std::string::npos) << md;
    EXPECT_NE(md.find("| worst horizontal | 1 |"), std::string::npos) << md;
    const std::string csv = runs_csv(runs);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
}

TEST(Aggregate, FixedFormatting) {
    EXPECT_EQ(fixed(0.0364, 3, true), "+0.036");
    EXPECT_EQ(fixed(-0.0004, 3, true), "+0.000");  // no "-0.000"
    EXPECT_EQ(fixed(-0.0004, 3, false), "0.000");
    EXPECT_EQ(fixed(-70.494, 2, true), "-70.49");
    EXPECT_EQ(fixed(108623.4, 0, false), "108623");
    EXPECT_EQ(fixed(std::numeric_limits<double>::quiet_NaN(), 2, true), "n/a");
}
