// Issue 11, item 3: a fault injected live into a running distributed run (gdnav fault) is stamped by the clock,
// applied by every member at that step and recorded in <out>/faults.yaml; re-running the scenario with that file
// (here in the direct layout) reproduces the faulted run bit for bit.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <thread>

#include <yaml-cpp/yaml.h>

#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

std::string fresh_domain() { return std::to_string(120 + static_cast<int>(getpid() % 25)); }

const char* const kRecorder =
    "components.recorder={type: recorder, topics: [gdnav/GnssSample, gdnav/PositionEstimate, gdnav/ControlCommands]}";

}  // namespace

TEST(LiveFaults, GnssFreezeInjectedIntoARunningRunIsReproducedFromTheRecord) {
    const fs::path dir = temp_dir("live-faults");
    const fs::path cfg = dir / "paper2.yaml";
    const Result s = run({GDNAV_GDNAV_EXE, "scenario", "--scenario", "2", "--seed", "3", "--set", kRecorder, "--out",
                          cfg.string()});
    ASSERT_EQ(s.exit_code, 0) << s.output;
    // Scenario #2 from t = -50 s for 40 s of simulated time, paced at 4x real time: about 10 s of wall time.
    const fs::path dist = dir / "distributed";
    const std::string domain = fresh_domain();
    const pid_t launcher = start({GDNAV_GDNAV_EXE, "run", "--scenario", cfg.string(), "--layout", "distributed",
                                  "--steps", "4000", "--realtime", "4", "--domain", domain, "--out", dist.string(),
                                  "--set", "run.member_timeout_s=10"},
                                 dir / "run.log");
    // Before step 0 there is no clock yet (exit 5) or it refuses ("not running yet"): retry until it takes it.
    // Mid-run: about 2 s of wall time (8 s of simulated time) after step 0.
    for (int i = 0; i < 600 && read_file(dir / "run.log").find("run 0 starts") == std::string::npos; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::this_thread::sleep_for(std::chrono::seconds(2));
    Result f;
    const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(90);
    while (std::chrono::steady_clock::now() < end) {
        f = run({GDNAV_GDNAV_EXE, "fault", "--domain", domain, "--target", "sensors_gnss", "--kind", "freeze", "--for",
                 "8", "--timeout", "5"},
                30.0);
        const bool early = f.exit_code == 5 || f.output.find("not running yet") != std::string::npos;
        if (!early) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
    }
    std::printf("%s", f.output.c_str());
    const int code = wait_for(launcher, 120.0);
    if (code == -1) kill(launcher, SIGINT);
    const std::string log = read_file(dir / "run.log");
    ASSERT_EQ(f.exit_code, 0) << f.output << log;
    ASSERT_EQ(code, 0) << log;
    EXPECT_NE(f.output.find("accepted: freeze of sensors_gnss"), std::string::npos) << f.output;
    EXPECT_NE(log.find("fault schedule version 1 adopted by every member"), std::string::npos) << log;

    // The record of the schedule names the step; a re-run with it gives the same samples.
    const YAML::Node applied = YAML::LoadFile((dist / "faults.yaml").string());
    ASSERT_EQ(applied["faults"].size(), 1u);
    const double at_s = applied["faults"][0]["at_s"].as<double>();
    std::printf("freeze injected live at t = %.2f s (until %.2f s)\n", at_s,
                applied["faults"][0]["until_s"].as<double>());
    EXPECT_GT(at_s, -48.0);
    EXPECT_LT(at_s, -10.0);
    const fs::path direct = dir / "direct";
    const Result r = run({GDNAV_GDNAV_EXE, "run", "--scenario", (dist / "run.yaml").string(), "--faults",
                          (dist / "faults.yaml").string(), "--layout", "direct", "--out", direct.string()},
                         120.0);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto a = read_digests(dist), b = read_digests(direct);
    ASSERT_EQ(a.size(), 3u);
    EXPECT_EQ(a, b) << "the live-faulted run and its re-run from faults.yaml differ";
    // And the fault changed the run: without it the records differ.
    const fs::path clean = dir / "clean";
    const Result c = run({GDNAV_GDNAV_EXE, "run", "--scenario", (dist / "run.yaml").string(), "--layout", "direct",
                          "--out", clean.string()},
                         120.0);
    ASSERT_EQ(c.exit_code, 0) << c.output;
    EXPECT_NE(read_digests(clean).at("gdnav/GnssSample"), a.at("gdnav/GnssSample"));
}
