// RunningStats against hand-computed statistics.
#include <gtest/gtest.h>

#include <cmath>

#include "metrics/linear_trend.hpp"
#include "metrics/running_stats.hpp"

using gdnav::metrics::RunningStats;

TEST(RunningStats, EmptyIsNaN) {
    RunningStats s;
    EXPECT_TRUE(s.empty());
    EXPECT_TRUE(std::isnan(s.mean()));
    EXPECT_TRUE(std::isnan(s.std()));
    EXPECT_TRUE(std::isnan(s.smax()));
    EXPECT_TRUE(std::isnan(s.last()));
}

TEST(RunningStats, TextbookPopulationStd) {
    // 2 4 4 4 5 5 7 9: mean 5, squared deviations 9+1+1+1+0+0+4+16 = 32, population variance 32/8 = 4, std 2.
    RunningStats s;
    for (double x : {2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0}) s.add(x);
    EXPECT_EQ(s.count(), 8u);
    EXPECT_NEAR(s.mean(), 5.0, 1e-15);
    EXPECT_NEAR(s.std(), 2.0, 1e-15);
    EXPECT_EQ(s.smax(), 9.0);
    EXPECT_EQ(s.last(), 9.0);
}

TEST(RunningStats, SignedMaxKeepsSignOfLargestMagnitude) {
    RunningStats s;
    for (double x : {1.0, -5.0, 3.0}) s.add(x);
    EXPECT_EQ(s.smax(), -5.0);
    EXPECT_EQ(s.last(), 3.0);
    EXPECT_NEAR(s.mean(), -1.0 / 3.0, 1e-15);
    // deviations from -1/3: 4/3, -14/3, 10/3 -> squares 16/9 + 196/9 + 100/9 = 312/9; / 3 = 104/9
    EXPECT_NEAR(s.std(), std::sqrt(104.0 / 9.0), 1e-14);
}

TEST(RunningStats, TieKeepsTheFirstSample) {
    RunningStats s;
    s.add(3.0);
    s.add(-3.0);
    EXPECT_EQ(s.smax(), 3.0);
}

TEST(RunningStats, AccurateWithLargeOffset) {
    // 1e9 + {4, 7, 13, 16}: mean 1e9 + 10, deviations -6 -3 3 6 -> variance 90/4 = 22.5. The naive
    // E[x^2] - E[x]^2 loses every digit here (x^2 ~ 1e18 carries ~1e2 of rounding), Welford keeps them.
    RunningStats s;
    for (double x : {4.0, 7.0, 13.0, 16.0}) s.add(1e9 + x);
    EXPECT_NEAR(s.mean(), 1e9 + 10.0, 1e-6);
    EXPECT_NEAR(s.std(), std::sqrt(22.5), 1e-6);
}

TEST(RunningStats, SingleSampleHasZeroStd) {
    RunningStats s;
    s.add(-2.5);
    EXPECT_EQ(s.mean(), -2.5);
    EXPECT_EQ(s.std(), 0.0);
    EXPECT_EQ(s.smax(), -2.5);
}

// LinearTrend: exact lines, a hand-computed noisy fit, degenerate inputs.
TEST(LinearTrend, ExactLineAndHandComputedFit) {
    gdnav::metrics::LinearTrend line;
    for (int i = 0; i < 1000; ++i) line.add(500.0 + 0.1 * i, 3.0e-3 - 2.0e-7 * (500.0 + 0.1 * i));
    EXPECT_NEAR(line.slope(), -2.0e-7, 2.0e-7 * 1e-9);  // y rounding (ulp 4e-19 on 2.9e-3) over a 100-s span
    EXPECT_NEAR(line.r2(), 1.0, 1e-12);
    // (0,1), (1,3), (2,2), (3,5): t_mean 1.5, y_mean 2.75, S_tt 5, S_ty 5.5, S_yy 8.75 -> slope 1.1,
    // r2 = 30.25 / 43.75 = 0.6914...
    gdnav::metrics::LinearTrend f;
    const double y[] = {1.0, 3.0, 2.0, 5.0};
    for (int i = 0; i < 4; ++i) f.add(i, y[i]);
    EXPECT_NEAR(f.slope(), 1.1, 1e-15);
    EXPECT_NEAR(f.r2(), 30.25 / 43.75, 1e-15);
}

TEST(LinearTrend, DegenerateInputsAreNaN) {
    gdnav::metrics::LinearTrend t;
    EXPECT_TRUE(std::isnan(t.slope()));
    t.add(1.0, 2.0);
    EXPECT_TRUE(std::isnan(t.slope()));
    t.add(1.0, 3.0);  // same t
    EXPECT_TRUE(std::isnan(t.slope()));
    gdnav::metrics::LinearTrend flat;
    flat.add(0.0, 1.0);
    flat.add(1.0, 1.0);
    EXPECT_EQ(flat.slope(), 0.0);
    EXPECT_TRUE(std::isnan(flat.r2()));
}
