// Scheduled faults (framework/faults, docs/faults.md). One paper scenario-#2 run (t = -50 .. 100 s)
// with every fault kind at its own time, in the direct and the distributed layouts: the recorded topics are
// bit-identical, and each fault's effect is checked in the recorded samples. A scheduled kill of an essential member
// ends the run at that step in both layouts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <yaml-cpp/yaml.h>

#include "process_util.hpp"
#include "record_reader.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;
namespace msg = gdnav::msg;

namespace {

// t = -50 + 0.01 k: at_s T is step 100 (T + 50).
std::uint64_t step_of(double t_s) { return static_cast<std::uint64_t>(std::llround((t_s + 50.0) * 100.0)); }

const char* const kFaults =
    "faults=["
    "{at_s: 20, until_s: 22, target: sensors_gnss, kind: drop},"
    "{at_s: 30, until_s: 31, target: sensors_magnetic, kind: freeze},"
    "{at_s: 40, until_s: 45, target: sensors_air, kind: bias, fields: {tas_mps: 5}},"
    "{at_s: 50, until_s: 55, target: sensors_air, kind: noise, fields: {tas_mps: 3}},"
    "{at_s: 60, until_s: 62, target: sensors_inertial, kind: delay, steps: 5},"
    "{at_s: 65, until_s: 70, target: sensors_atmospheric, kind: loss, p: 0.5},"
    "{at_s: 75, until_s: 76, target: sensors_air, kind: nan, fields: [aoa_rad]},"
    "{at_s: 80, until_s: 90, target: nav_att, kind: kill}]";
const char* const kRecorder =
    "components.recorder={type: recorder, topics: [gdnav/Truth, gdnav/GnssSample, gdnav/MagSample, gdnav/AirSample, "
    "gdnav/AtmSample, gdnav/ImuSample, gdnav/AttitudeEstimate]}";

fs::path faulted_config() {
    const fs::path dir = temp_dir("sched-faults");
    const fs::path cfg = dir / "paper2_faults.yaml";
    const Result r = run({GDNAV_GDNAV_EXE, "scenario", "--scenario", "2", "--seed", "1", "--set", kFaults, "--set",
                          kRecorder, "--set", "run.duration_s=150", "--out", cfg.string()});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return cfg;
}

template <class T>
std::map<std::uint64_t, T> by_step(const fs::path& out, const std::string& topic) {
    std::map<std::uint64_t, T> m;
    for (const T& s : read_records<T>(out, topic)) m[s.stamp().step()] = s;
    return m;
}

// Recorded sample rows by the step the recorder received them at (the delay keeps the old stamp, so the delayed
// topic is read in order instead).
template <class T>
std::vector<T> in_order(const fs::path& out, const std::string& topic) {
    return read_records<T>(out, topic);
}

}  // namespace

TEST(ScheduledFaults, EveryKindIsBitIdenticalAcrossLayoutsAndVisibleInTheRecord) {
    const fs::path cfg = faulted_config();
    const fs::path direct = temp_dir("sched-direct"), dist = temp_dir("sched-dist");
    const Result a = run({GDNAV_GDNAV_EXE, "run", "--scenario", cfg.string(), "--layout", "direct", "--out",
                          direct.string()}, 120.0);
    ASSERT_EQ(a.exit_code, 0) << a.output;
    const Result b = run({GDNAV_GDNAV_EXE, "run", "--scenario", cfg.string(), "--layout", "distributed", "--out",
                          dist.string(), "--set", "run.member_timeout_s=10"}, 600.0);
    ASSERT_EQ(b.exit_code, 0) << b.output;
    const auto da = read_digests(direct), db = read_digests(dist);
    ASSERT_EQ(da.size(), 7u);
    EXPECT_EQ(da, db) << "direct and distributed records differ";

    // drop: no GnssSample at the 200 steps of [20, 22) s.
    const auto gnss = by_step<msg::GnssSample>(direct, "gdnav/GnssSample");
    int dropped = 0;
    for (std::uint64_t k = step_of(20); k < step_of(22); ++k) dropped += gnss.count(k) == 0;
    EXPECT_EQ(dropped, 200);
    EXPECT_EQ(gnss.count(step_of(20) - 1), 1u);
    EXPECT_EQ(gnss.count(step_of(22)), 1u);

    // freeze: MagSample of [30, 31) s repeats the sample of the step before, re-stamped.
    const auto mag = by_step<msg::MagSample>(direct, "gdnav/MagSample");
    const auto before = mag.at(step_of(30) - 1).b_b_nT();
    int frozen = 0;
    for (std::uint64_t k = step_of(30); k < step_of(31); ++k) frozen += mag.at(k).b_b_nT() == before;
    EXPECT_EQ(frozen, 100);
    EXPECT_NE(mag.at(step_of(31)).b_b_nT(), before);

    // bias and noise on the Pitot airspeed: measured - true airspeed.
    const auto truth = by_step<msg::Truth>(direct, "gdnav/Truth");
    const auto air = by_step<msg::AirSample>(direct, "gdnav/AirSample");
    auto stats = [&](double t0, double t1) {
        double s = 0, s2 = 0;
        int n = 0;
        for (std::uint64_t k = step_of(t0); k < step_of(t1); ++k) {
            const double e = air.at(k).tas_mps() - truth.at(k).tas_mps();
            s += e, s2 += e * e, ++n;
        }
        const double m = s / n;
        return std::pair{m, std::sqrt(s2 / n - m * m)};
    };
    const auto [m_before, sd_before] = stats(35, 40);
    const auto [m_bias, sd_bias] = stats(40, 45);
    const auto [m_noise, sd_noise] = stats(50, 55);
    std::printf("airspeed error: before %.3f +- %.3f m/s; bias 5: %.3f +- %.3f; noise 3: %.3f +- %.3f\n", m_before,
                sd_before, m_bias, sd_bias, m_noise, sd_noise);
    EXPECT_NEAR(m_bias - m_before, 5.0, 0.2);
    EXPECT_NEAR(sd_bias, sd_before, 0.05);
    EXPECT_NEAR(sd_noise, std::hypot(3.0, sd_before), 0.3);  // 500 samples: sd known to ~3 %

    // delay: in [60, 62) s the ImuSample received at step k is the one of step k - 5 (it keeps its stamp).
    const auto imu = in_order<msg::ImuSample>(direct, "gdnav/ImuSample");
    const std::uint64_t k0 = imu.front().stamp().step();
    int late = 0;
    for (std::uint64_t k = step_of(60); k < step_of(62); ++k) late += imu.at(k - k0).stamp().step() == k - 5;
    EXPECT_EQ(late, 200);
    EXPECT_EQ(imu.at(step_of(62) - k0).stamp().step(), step_of(62));

    // loss p = 0.5 on AtmSample in [65, 70) s: 500 Bernoulli draws, 250 +- 11.
    const auto atm = by_step<msg::AtmSample>(direct, "gdnav/AtmSample");
    int lost = 0;
    for (std::uint64_t k = step_of(65); k < step_of(70); ++k) lost += atm.count(k) == 0;
    std::printf("loss p=0.5: %d of 500 AtmSample dropped\n", lost);
    EXPECT_NEAR(lost, 250, 50);
    for (std::uint64_t k = step_of(60); k < step_of(65); ++k) EXPECT_EQ(atm.count(k), 1u);

    // nan: the vane angle of [75, 76) s is NaN; the airspeed is not; the air-data filter rejected those samples.
    int nans = 0;
    for (std::uint64_t k = step_of(75); k < step_of(76); ++k)
        nans += std::isnan(air.at(k).aoa_rad()) && std::isfinite(air.at(k).tas_mps());
    EXPECT_EQ(nans, 100);
    EXPECT_NE(a.output.find("rejected samples: AirSample 100"), std::string::npos) << a.output;

    // kill 80-90 s: no AttitudeEstimate for 1000 steps, then the member created anew publishes again.
    const auto att = by_step<msg::AttitudeEstimate>(direct, "gdnav/AttitudeEstimate");
    int missing = 0;
    for (std::uint64_t k = step_of(80); k < step_of(90); ++k) missing += att.count(k) == 0;
    EXPECT_EQ(missing, 1000);
    EXPECT_EQ(att.count(step_of(90)), 1u);
    for (const auto* out : {&a.output, &b.output}) {
        EXPECT_NE(out->find("killed by a scheduled fault"), std::string::npos) << *out;
        EXPECT_NE(out->find("restarted by a scheduled fault"), std::string::npos) << *out;
    }
}

TEST(ScheduledFaults, KillingAnEssentialMemberEndsTheRunAtThatStepInEveryLayout) {
    // The test chain: chain_plant is essential; killed at t = 5 s (step 500).
    const fs::path dir = temp_dir("sched-essential");
    YAML::Node doc = YAML::LoadFile(chain_scenario());
    doc["faults"] = YAML::Load("[{at_s: 5, target: chain_plant, kind: kill}]");
    const fs::path cfg = dir / "chain_kill.yaml";
    {
        std::ofstream f(cfg);
        f << doc;
    }
    for (const std::string layout : {"direct", "distributed"}) {
        const fs::path out = dir / layout;
        const Result r = run({testchain_exe(), "run", "--scenario", cfg.string(), "--layout", layout, "--out",
                              out.string()}, 120.0);
        EXPECT_EQ(r.exit_code, 3) << layout << "\n" << r.output;
        EXPECT_NE(r.output.find("essential member 'chain_plant' killed by a scheduled fault at step 500"),
                  std::string::npos) << layout << "\n" << r.output;
        const YAML::Node s = YAML::LoadFile((out / "clock_summary.yaml").string());
        EXPECT_FALSE(s["completed"].as<bool>()) << layout;
        EXPECT_EQ(s["steps_done"].as<std::uint64_t>(), 500u) << layout;
    }
}
