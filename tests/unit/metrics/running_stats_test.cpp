// RunningStats against hand-computed statistics.
#include <gtest/gtest.h>

#include <cmath>

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
