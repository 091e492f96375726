// The Mugin flies the paper's missions in turbulence with guidance and control closed on truth
// (truth_as_estimate), and the same seed gives bit-identical truth in the three layouts.
//
// "Outside manoeuvres" = t >= 0, aileron channel holding a bearing, elevator holding a pressure altitude, and at
// least 30 s after the last operation change (the transients of turns and speed/altitude changes excluded).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "gnc/modes.hpp"
#include "math/rotation.hpp"
#include "process_util.hpp"
#include "record_reader.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

using gdnav::math::kDeg;

// Writes a copy of a scenario with a recorder limited to Truth + GuidanceTargets at `decimation`.
fs::path scenario_copy(const std::string& name, int decimation, const fs::path& dir, bool all_topics = false) {
    YAML::Node doc = YAML::LoadFile(std::string(GDNAV_SOURCE_DIR) + "/config/scenarios/" + name + ".yaml");
    if (!doc["components"]["recorder"]) doc["components"]["recorder"]["type"] = "recorder";
    if (!all_topics)
        doc["components"]["recorder"]["topics"] = std::vector<std::string>{"gdnav/Truth", "gdnav/GuidanceTargets"};
    doc["components"]["recorder"]["decimation"] = decimation;
    const fs::path f = dir / (name + ".yaml");
    std::ofstream(f) << doc;
    return f;
}

struct Stats {
    double n{0}, s{0}, s2{0};
    void add(double x) { n += 1; s += x; s2 += x * x; }
    [[nodiscard]] double std() const { return std::sqrt(std::max(0.0, s2 / n - (s / n) * (s / n))); }
};

struct FlightQuality {
    Stats hp, tas, chi;
    double max_bank_deg{0}, min_tas{1e9}, max_tas{0}, max_hp_dev{0};
    bool finite{true};
};

FlightQuality evaluate(const fs::path& out) {
    const auto truth = read_records<gdnav::msg::Truth>(out, "gdnav/Truth");
    const auto guid = read_records<gdnav::msg::GuidanceTargets>(out, "gdnav/GuidanceTargets");
    EXPECT_EQ(truth.size(), guid.size());
    FlightQuality q;
    std::uint32_t last_op = 0;
    double op_start = -1e9;
    for (std::size_t i = 0; i < std::min(truth.size(), guid.size()); ++i) {
        const auto& t = truth[i];
        const auto& g = guid[i];
        const double time = t.stamp().t_s();
        for (double v : {t.lat_rad(), t.h_m(), t.tas_mps(), t.q_nb()[0]}) q.finite = q.finite && std::isfinite(v);
        if (g.operation() != last_op) {
            last_op = g.operation();
            op_start = time;
        }
        q.max_bank_deg = std::max(q.max_bank_deg, std::abs(t.euler_rad()[2]) / kDeg);
        q.min_tas = std::min(q.min_tas, t.tas_mps());
        q.max_tas = std::max(q.max_tas, t.tas_mps());
        using gdnav::gnc::AileronMode;
        using gdnav::gnc::ElevatorMode;
        const bool hold = g.aileron_mode() == gdnav::gnc::to_octet(AileronMode::bearing) &&
                          g.elevator_mode() == gdnav::gnc::to_octet(ElevatorMode::pressure_altitude);
        if (g.elevator_mode() == gdnav::gnc::to_octet(ElevatorMode::pressure_altitude))
            q.max_hp_dev = std::max(q.max_hp_dev, std::abs(t.Hp_m() - g.elevator_target()));
        if (time < 0.0 || !hold || time - op_start < 30.0) continue;
        q.hp.add(t.Hp_m() - g.elevator_target());
        q.tas.add(t.tas_mps() - g.throttle_target());
        const double chi = std::atan2(t.v_n_mps()[1], t.v_n_mps()[0]);
        q.chi.add(std::remainder(chi - g.aileron_target(), 2.0 * std::numbers::pi) / kDeg);
    }
    return q;
}

void fly(const std::string& scenario, const std::string& tag) {
    const auto dir = temp_dir(tag);
    const fs::path file = scenario_copy(scenario, 10, dir);
    const Result r = run({GDNAV_GDNAV_EXE, "run", "--scenario", file.string(), "--layout", "direct", "--out",
                          (dir / "out").string()},
                         600.0);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const FlightQuality q = evaluate(dir / "out");
    std::printf("%s: outside manoeuvres Hp err std %.2f m, TAS err std %.3f m/s, bearing err std %.2f deg "
                "(%.0f samples); max bank %.1f deg, TAS [%.1f, %.1f] m/s\n",
                scenario.c_str(), q.hp.std(), q.tas.std(), q.chi.std(), q.hp.n, q.max_bank_deg, q.min_tas, q.max_tas);
    EXPECT_TRUE(q.finite);
    EXPECT_GT(q.hp.n, 100.0);
    EXPECT_LE(q.hp.std(), 10.0);   // reference: 8.2 m
    EXPECT_LE(q.tas.std(), 0.6);   // reference: 0.44 m/s
    EXPECT_LE(q.chi.std(), 1.5);   // reference: 1.05 deg
}

}  // namespace

TEST(Flight, Scenario1MissionOnTruthInTurbulence) { fly("truth_loop_s1", "s1"); }

TEST(Flight, Scenario2MissionOnTruthInTurbulence) { fly("truth_loop_s2", "s2"); }

TEST(Flight, FiftySeedsOfScenario2FlyWithoutDivergenceOrEnvelopeExit) {
    // The paper's scenario #2 generator: each seed draws its own mission (8 turns), wind, INSA offsets,
    // Earth-field deviations and turbulence.
    const auto dir = temp_dir("seeds");
    const fs::path file = scenario_copy("paper2_truth", 100, dir);
    // Two runs at a time (the test has the machine to itself: RUN_SERIAL).
    for (int first = 1; first <= 50; first += 2) {
        std::vector<std::pair<int, pid_t>> started;
        for (int seed = first; seed <= std::min(first + 1, 50); ++seed) {
            const fs::path out = dir / ("seed" + std::to_string(seed));
            started.emplace_back(seed, start({GDNAV_GDNAV_EXE, "run", "--scenario", file.string(), "--layout",
                                              "direct", "--seed", std::to_string(seed), "--out", out.string()},
                                             out.string() + ".log"));
        }
        for (const auto& [seed, pid] : started) {
            const fs::path out = dir / ("seed" + std::to_string(seed));
            ASSERT_EQ(wait_for(pid, 300.0), 0) << read_file(out.string() + ".log");
            const FlightQuality q = evaluate(out);
            SCOPED_TRACE("seed " + std::to_string(seed));
            EXPECT_TRUE(q.finite);
            EXPECT_LT(q.max_bank_deg, 25.0);
            EXPECT_GT(q.min_tas, 20.0);
            EXPECT_LT(q.max_tas, 40.0);
            EXPECT_LT(q.max_hp_dev, 100.0);
        }
    }
}

// Truth, every sensor topic, the three navigation estimates, guidance targets and controls.
TEST(Flight, SameSeedBitIdenticalTruthMeasurementsAndEstimatesInAllLayouts) {
    const auto dir = temp_dir("layouts");
    const fs::path file = scenario_copy("nav_loop_s2", 1, dir, true);
    std::map<std::string, std::string> first;
    for (const char* layout : {"direct", "composed", "distributed"}) {
        const fs::path out = dir / layout;
        const Result r = run({GDNAV_GDNAV_EXE, "run", "--scenario", file.string(), "--layout", layout, "--steps",
                              "3000", "--out", out.string()},
                             300.0);
        ASSERT_EQ(r.exit_code, 0) << r.output;
        const auto d = read_digests(out);
        ASSERT_EQ(d.size(), 11u);
        if (first.empty())
            first = d;
        else
            EXPECT_EQ(d, first) << layout;
    }
}

TEST(Flight, BadAircraftOrMissionFileGivesOneErrorAndStartsNothing) {
    struct Case {
        const char* what;
        const char* file;            // file under config/ to corrupt
        std::string from, to;        // text replacement
        const char* must_contain;
    };
    const std::vector<Case> cases{
        {"negative mass", "aircraft/mugin.yaml", "full_kg: 19.715", "full_kg: -19.715", "mass.full_kg"},
        {"unknown operation", "missions/scenario2_example.yaml", "op: turn", "op: loop", "loop"},
        {"missing key", "missions/scenario2_example.yaml", "until: {trigger: time, t_s: 192.6}", "", "until"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.what);
        // A private copy of config/ with one file corrupted.
        const auto dir = temp_dir("badcfg");
        fs::copy(std::string(GDNAV_SOURCE_DIR) + "/config", dir / "config", fs::copy_options::recursive);
        const fs::path bad = dir / "config" / c.file;
        std::string text = read_file(bad);
        const auto pos = text.find(c.from);
        ASSERT_NE(pos, std::string::npos);
        text.replace(pos, c.from.size(), c.to);
        std::ofstream(bad) << text;
        const std::string cmd = "GDNAV_CONFIG_DIR=" + (dir / "config").string();
        const Result r = run({"/usr/bin/env", cmd, GDNAV_GDNAV_EXE, "run", "--scenario", "truth_loop_s2", "--layout",
                              "distributed", "--out", (dir / "out").string()},
                             60.0);
        EXPECT_NE(r.exit_code, 0) << r.output;
        std::size_t lines = 0;
        for (char ch : r.output) lines += (ch == '\n');
        EXPECT_EQ(lines, 1u) << r.output;
        EXPECT_NE(r.output.find(c.must_contain), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(c.file), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(dir / "out" / "processes.yaml"));
    }
}
