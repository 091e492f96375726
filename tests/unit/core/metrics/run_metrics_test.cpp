// Per-run metrics: window, distance since t_GNSS, percentages and the metrics.yaml record.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <unistd.h>

#include "config/config.hpp"
#include "metrics/run_record.hpp"

using namespace gdnav::metrics;

namespace {

NavErrors with_h(double h) {
    NavErrors e;
    e.h_m = h;
    e.hor_m = std::fabs(h);
    return e;
}

std::filesystem::path temp_file(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("gdnav_metrics_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir / name;
}

}  // namespace

TEST(RunMetrics, WindowStartsAtZeroAndDiscardsTheTransient) {
    RunMetrics m(100.0);
    for (double t : {-1.0, -0.5, 0.0, 0.5, 1.0}) m.add_errors(t, 0.5, with_h(t));
    const RunningStats& h = m.stats(Signal::h);
    EXPECT_EQ(h.count(), 3u);  // t = 0, 0.5, 1
    EXPECT_NEAR(h.mean(), 0.5, 1e-15);
    EXPECT_NEAR(h.std(), std::sqrt(1.0 / 6.0), 1e-15);  // deviations -0.5, 0, 0.5 -> 0.5/3
    EXPECT_EQ(h.smax(), 1.0);
    EXPECT_EQ(h.last(), 1.0);
    EXPECT_EQ(m.t_last_s(), 1.0);
}

TEST(RunMetrics, DistanceSinceGnssLossIsCountedFromTGnss) {
    // 100 Hz steps from t = 90 to 110 s with ground speed 30 m/s: only [100, 110] counts -> 300 m.
    RunMetrics m(100.0);
    for (int k = 9000; k <= 11000; ++k) m.add_ground_speed(k * 0.01, 0.01, 30.0);
    EXPECT_NEAR(m.distance_since_gnss_m(), 300.0, 1e-9);
    // Speed v = t (linear): integral over [100, 110] = (110^2 - 100^2) / 2 = 1050 m (trapezoids are exact).
    RunMetrics lin(100.0);
    for (int k = 9000; k <= 11000; ++k) lin.add_ground_speed(k * 0.01, 0.01, k * 0.01);
    EXPECT_NEAR(lin.distance_since_gnss_m(), 1050.0, 1e-7);
}

TEST(RunMetrics, FinalPercentOfDistance) {
    RunMetrics m(0.0);
    for (int k = 0; k <= 100; ++k) m.add_ground_speed(k * 0.01, 0.01, 50.0);  // 50 m
    NavErrors e;
    e.hor_m = 5.0;
    e.cross_m = -3.0;
    e.along_m = 4.0;
    m.add_errors(1.0, 0.01, e);
    EXPECT_NEAR(m.final_percent(Signal::hor), 10.0, 1e-12);
    EXPECT_NEAR(m.final_percent(Signal::cross), -6.0, 1e-12);
    EXPECT_NEAR(m.final_percent(Signal::along), 8.0, 1e-12);
    RunMetrics none(100.0);
    none.add_errors(1.0, 0.01, e);
    EXPECT_TRUE(std::isnan(none.final_percent(Signal::hor)));  // no distance flown yet
}

TEST(RunRecord, RoundTripsEveryBit) {
    RunMetrics m(0.2, 0.0, 0.1);  // t_GNSS 0.2 s, attitude trend from 0.1 s
    for (int k = 0; k < 50; ++k) {
        NavErrors e;
        e.yaw_rad = 0.1 * k / 3.0;
        e.rot_rad = std::sqrt(2.0) * k;
        e.h_m = -1.0 / (k + 1.0);
        e.hor_m = 3.0 * k + std::sin(k);
        m.add_errors(k * 0.01, 0.01, e);
    }
    const RunRecord r = make_run_record(m, true, 7, 42, 50);
    const auto file = temp_file("metrics.yaml");
    write_run_record(file, r);
    const RunRecord back = read_run_record(file);
    EXPECT_TRUE(back.complete);
    EXPECT_EQ(back.seed, 7u);
    EXPECT_EQ(back.run_index, 42u);
    EXPECT_EQ(back.samples, 50u);
    for (std::size_t i = 0; i < kSignalCount; ++i) {
        EXPECT_EQ(back.signals[i].mean, r.signals[i].mean) << i;
        EXPECT_EQ(back.signals[i].std, r.signals[i].std) << i;
        EXPECT_EQ(back.signals[i].max, r.signals[i].max) << i;
        EXPECT_EQ(back.signals[i].final, r.signals[i].final) << i;
    }
    EXPECT_TRUE(std::isnan(back.hor_pct));  // no distance: written as .nan
    // Trends: rot = sqrt(2) k = 100 sqrt(2) t exactly (from t = 0.1 s); hor from t = 0.2 s, nearly linear.
    EXPECT_EQ(back.att_trend_from_s, 0.1);
    EXPECT_NEAR(back.att_slope_rad_per_s, 100.0 * std::sqrt(2.0), 1e-9);
    EXPECT_EQ(back.hor_slope_mps, r.hor_slope_mps);
    EXPECT_EQ(back.hor_r2, r.hor_r2);
    EXPECT_GT(back.hor_r2, 0.99);
    EXPECT_EQ(to_yaml(back), to_yaml(r));
    EXPECT_TRUE(run_record_complete(file));
}

TEST(RunRecord, IncompleteMissingOrBrokenFilesAreNotComplete) {
    RunMetrics m(100.0);
    const auto file = temp_file("partial.yaml");
    write_run_record(file, make_run_record(m, false, 1, 0, 0));
    EXPECT_FALSE(run_record_complete(file));
    EXPECT_FALSE(read_run_record(file).complete);
    EXPECT_FALSE(run_record_complete(temp_file("missing.yaml")));
    std::ofstream(temp_file("broken.yaml")) << "complete: [oops\n";
    EXPECT_FALSE(run_record_complete(temp_file("broken.yaml")));
    EXPECT_THROW(read_run_record(temp_file("missing.yaml")), gdnav::config::ConfigError);
    std::filesystem::remove_all(temp_file("").parent_path());
}

TEST(RunRecord, SeventeenSignificantDigits) {
    EXPECT_EQ(format_double17(0.1), "0.10000000000000001");
    EXPECT_EQ(format_double17(-2.0), "-2");
    EXPECT_EQ(format_double17(std::numeric_limits<double>::quiet_NaN()), ".nan");
    EXPECT_EQ(format_double17(-std::numeric_limits<double>::infinity()), "-.inf");
}
