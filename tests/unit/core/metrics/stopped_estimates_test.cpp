// An estimator that stops before the end of the run: the final figures are those of the last step with every
// estimate, divided by the distance flown up to that step, and the record says so; records of runs without a
// reference trajectory carry no error metrics.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <unistd.h>

#include "config/config.hpp"
#include "metrics/aggregate.hpp"
#include "metrics/report_tables.hpp"
#include "metrics/run_record.hpp"

using namespace gdnav::metrics;

namespace {

std::filesystem::path temp_file(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / ("gdnav_stopped_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir / name;
}

// A 10 s flight at 100 Hz, GNSS lost at t = 0, ground speed 10 m/s, horizontal error 0.1 m per second flown
// (e = 0.1 t); the position estimate stops after t = stop_s (never with stop_s > 10).
RunMetrics flight(double stop_s) {
    RunMetrics m(0.0);
    for (int k = 0; k <= 1000; ++k) {
        const double t = k * 0.01;
        m.add_ground_speed(t, 0.01, 10.0);
        const bool pos = t <= stop_s + 0.005;
        m.note_estimates(t, 0.01, {true, true, pos});
        if (!pos) continue;
        NavErrors e;
        e.hor_m = 0.1 * t;
        e.cross_m = 0.06 * t;
        e.along_m = -0.08 * t;
        e.rot_rad = 0.001;
        m.add_errors(t, 0.01, e);
    }
    return m;
}

}  // namespace

TEST(StoppedEstimates, FinalFigureAtTheLastEstimateOverTheDistanceFlownUpToIt) {
    const RunMetrics m = flight(4.0);
    EXPECT_FALSE(m.estimates_complete());
    EXPECT_TRUE(m.estimate_stopped(Estimate::position));
    EXPECT_FALSE(m.estimate_stopped(Estimate::attitude));
    EXPECT_NEAR(m.t_last_s(), 4.0, 1e-12);
    EXPECT_NEAR(m.last_estimate_s(Estimate::position), 4.0, 1e-12);
    EXPECT_NEAR(m.last_estimate_s(Estimate::attitude), 10.0, 1e-12);
    // Constant speed: the trapezoids are exact, 40 m flown up to t = 4 s, 100 m to the end.
    EXPECT_NEAR(m.distance_at_t_last_m(), 40.0, 1e-9);
    EXPECT_NEAR(m.distance_since_gnss_m(), 100.0, 1e-9);
    // Final error 0.4 m at t = 4 s: 1 % of the 40 m flown then (0.4 % of the whole 100 m would understate it 2.5x).
    EXPECT_NEAR(m.stats(Signal::hor).last(), 0.4, 1e-12);
    EXPECT_NEAR(m.final_percent(Signal::hor), 1.0, 1e-9);
    EXPECT_NEAR(m.final_percent(Signal::cross), 0.6, 1e-9);
    EXPECT_NEAR(m.final_percent(Signal::along), -0.8, 1e-9);
    EXPECT_EQ(m.stats(Signal::hor).count(), 401u);  // t = 0 .. 4 s
}

TEST(StoppedEstimates, CompleteRunKeepsTheWholeFlightsDistance) {
    const RunMetrics m = flight(100.0);
    EXPECT_TRUE(m.estimates_complete());
    EXPECT_NEAR(m.final_percent(Signal::hor), 1.0, 1e-9);  // 1 m after 100 m
    EXPECT_EQ(m.final_percent(Signal::hor), 100.0 * m.stats(Signal::hor).last() / m.distance_since_gnss_m());
    // An estimate that never came is not complete either.
    RunMetrics never(0.0);
    never.note_estimates(0.0, 0.01, {true, true, false});
    EXPECT_FALSE(never.estimates_complete());
    EXPECT_TRUE(std::isnan(never.last_estimate_s(Estimate::position)));
    // Nothing noted (a run that ended before the metrics window): nothing is claimed.
    EXPECT_TRUE(RunMetrics(0.0).estimates_complete());
}

TEST(StoppedEstimates, RecordCarriesTheNewKeysOnlyWhenIncompleteAndRoundTrips) {
    const std::string complete = to_yaml(make_run_record(flight(100.0), true, 1, 0, 1001));
    for (const char* key : {"estimates_complete", "distance_at_t_end_m", "last_estimate_s", "reference"})
        EXPECT_EQ(complete.find(key), std::string::npos) << key;

    const RunRecord r = make_run_record(flight(4.0), true, 1, 3, 1001);
    const std::string yaml = to_yaml(r);
    EXPECT_NE(yaml.find("complete: true\nestimates_complete: false\n"), std::string::npos) << yaml;
    EXPECT_NE(yaml.find("last_estimate_s: {air_data: 10, attitude: 10, position: 4"), std::string::npos) << yaml;
    const auto file = temp_file("stopped.yaml");
    write_run_record(file, r);
    const RunRecord back = read_run_record(file);
    EXPECT_FALSE(back.estimates_complete);
    EXPECT_EQ(back.distance_t_end_m, r.distance_t_end_m);
    EXPECT_EQ(back.final_distance_m(), r.distance_t_end_m);
    EXPECT_EQ(back.hor_pct, r.hor_pct);
    for (std::size_t i = 0; i < kEstimateCount; ++i) EXPECT_EQ(back.last_estimate_s[i], r.last_estimate_s[i]) << i;
    EXPECT_EQ(to_yaml(back), yaml);
    EXPECT_TRUE(run_record_complete(file));  // the run itself ended normally: a batch does not run it again

    // The batch: the distance column is the distance each run's % divides by; the run is marked in the ranking.
    RunRecord whole = make_run_record(flight(100.0), true, 2, 4, 1001);
    const BatchAggregate b = aggregate_runs({r, whole});
    EXPECT_NEAR(b.distance.mean, 0.5 * (40.0 + 100.0), 1e-9);
    const std::string md = paper_tables_markdown({{"#t", b, {r, whole}}}, "# test");
    EXPECT_NE(md.find("| 3 (estimates stop at t = 4.00 s) |"), std::string::npos) << md;
    const std::string csv = runs_csv({r, whole});
    EXPECT_NE(csv.find(",estimates_complete,distance_at_t_end_m\n"), std::string::npos) << csv;
    std::filesystem::remove_all(file.parent_path());
}

TEST(StoppedEstimates, UnreferencedRecordHasNoErrorMetricsAndCannotBeReadAsOne) {
    const RunRecord r = make_unreferenced_record(true, 1, 0, 16001, 100.0);
    const std::string yaml = to_yaml(r);
    EXPECT_NE(yaml.find("complete: true\nreference: none\n"), std::string::npos) << yaml;
    for (const char* key : {"signals", "final_percent", "distance_since_gnss_m", "t_end_s"})
        EXPECT_EQ(yaml.find(key), std::string::npos) << key;
    const auto file = temp_file("unreferenced.yaml");
    write_run_record(file, r);
    EXPECT_TRUE(run_record_complete(file));
    try {
        (void)read_run_record(file);
        ADD_FAILURE() << "read_run_record accepted a record without error metrics";
    } catch (const gdnav::config::ConfigError& e) {
        EXPECT_NE(std::string(e.what()).find("no reference trajectory"), std::string::npos) << e.what();
    }
    std::filesystem::remove_all(file.parent_path());
}
