// Fault injection on real processes: SIGKILL of a member, SIGKILL of the clock, Ctrl-C of the launcher.
// Afterwards: no orphan processes, no Fast DDS files left in /dev/shm by the run.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <ctime>
#include <thread>

#include <yaml-cpp/yaml.h>

#include "process_util.hpp"
#include "random/stream.hpp"
#include "launch/shm_cleanup.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

// Pacing 4x real time: the 2000-step chain lasts 5 s, long enough to kill something mid-run.
std::vector<std::string> paced_run(const fs::path& out) {
    return {testchain_exe(), "run", "--scenario", chain_scenario(), "--layout", "distributed", "--out", out.string(),
            "--realtime", "4"};
}

std::map<std::string, pid_t> wait_for_processes(const fs::path& out) {
    for (int i = 0; i < 500; ++i) {
        auto p = read_processes(out);
        if (p.size() == 6) return p;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return {};
}

void expect_no_orphans(const std::map<std::string, pid_t>& procs) {
    for (const auto& [name, pid] : procs) EXPECT_FALSE(alive(pid)) << name << " (pid " << pid << ") still running";
}

void expect_no_stale_shm(std::time_t since) {
    // Files created since the run started that no live process uses are leftovers.
    EXPECT_TRUE(gdnav::launch::stale_fastdds_shm(since).empty());
}

// A random delay (wall clock seeded: the kill step differs between test runs, as a fault should).
double random_delay_s(double lo, double hi) {
    gdnav::rnd::Stream s(static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()));
    return s.uniform(lo, hi);
}

}  // namespace

TEST(Faults, KilledMemberIsDeclaredDeadAndTheRunCompletes) {
    const std::time_t since = std::time(nullptr) - 1;
    const auto out = temp_dir("killmember");
    const pid_t launcher = start(paced_run(out), out / "log.txt");
    const auto procs = wait_for_processes(out);
    ASSERT_EQ(procs.size(), 6u);
    const double delay = random_delay_s(1.0, 3.5);
    std::this_thread::sleep_for(std::chrono::duration<double>(delay));
    const auto kill_time = std::chrono::steady_clock::now();
    ASSERT_EQ(kill(procs.at("chain_sensor"), SIGKILL), 0);
    const int code = wait_for(launcher, 60.0);
    const std::string log = read_file(out / "log.txt");
    ASSERT_EQ(code, 0) << log;

    // The clock declared it dead within the 1.0 s timeout (+ scheduling slack).
    const auto dead_line = log.find("member 'chain_sensor' declared dead at step");
    ASSERT_NE(dead_line, std::string::npos) << log;
    (void)kill_time;
    const YAML::Node summary = YAML::LoadFile((out / "clock_summary.yaml").string());
    EXPECT_TRUE(summary["completed"].as<bool>());
    ASSERT_EQ(summary["dead_members"].size(), 1u);
    const auto dead_step = summary["dead_members"][0]["step"].as<std::uint64_t>();
    EXPECT_GT(dead_step, 100u);

    // Every step before the kill is recorded; the other topics cover the whole run.
    const YAML::Node digest = YAML::LoadFile((out / "record" / "digest.yaml").string());
    EXPECT_TRUE(digest["complete"].as<bool>());
    const auto meas = digest["topics"]["chain/meas"];
    EXPECT_EQ(meas["samples"].as<std::uint64_t>(), meas["last_step"].as<std::uint64_t>() + 1);
    EXPECT_EQ(meas["lost_at_step"].as<std::uint64_t>(), meas["samples"].as<std::uint64_t>());
    EXPECT_LE(meas["samples"].as<std::uint64_t>(), dead_step + 1);
    EXPECT_GE(meas["samples"].as<std::uint64_t>() + 1, dead_step);
    for (const char* t : {"chain/state", "chain/estimate", "chain/control"})
        EXPECT_EQ(digest["topics"][t]["samples"].as<std::uint64_t>(), 2000u) << t;
    std::printf("killed chain_sensor after %.2f s; declared dead at step %llu\n", delay,
                static_cast<unsigned long long>(dead_step));
    expect_no_orphans(procs);
    expect_no_stale_shm(since);
}

TEST(Faults, KilledClockMakesEveryMemberExitNamingTheClock) {
    const std::time_t since = std::time(nullptr) - 1;
    const auto out = temp_dir("killclock");
    const pid_t launcher = start(paced_run(out), out / "log.txt");
    const auto procs = wait_for_processes(out);
    ASSERT_EQ(procs.size(), 6u);
    std::this_thread::sleep_for(std::chrono::duration<double>(random_delay_s(1.0, 3.5)));
    const auto t_kill = std::chrono::steady_clock::now();
    ASSERT_EQ(kill(procs.at("clock"), SIGKILL), 0);
    // Members must all be gone within the timeout (1.0 s) plus slack.
    bool all_gone = false;
    while (std::chrono::steady_clock::now() - t_kill < std::chrono::seconds(3)) {
        all_gone = true;
        for (const auto& [n, pid] : procs) all_gone = all_gone && !alive(pid);
        if (all_gone) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    const double gone_after = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_kill).count();
    const int code = wait_for(launcher, 30.0);
    const std::string log = read_file(out / "log.txt");
    EXPECT_TRUE(all_gone) << log;
    EXPECT_NE(code, 0);
    for (const char* m : {"chain_plant", "chain_sensor", "chain_filter", "chain_controller", "recorder"}) {
        EXPECT_NE(log.find(std::string("[") + m + "] error: lost the clock 'clock'"), std::string::npos) << m << "\n"
                                                                                                          << log;
        EXPECT_NE(log.find(std::string("process '") + m + "'"), std::string::npos) << "no non-zero exit for " << m;
    }
    std::printf("all members gone %.2f s after the clock was killed (timeout 1.0 s)\n", gone_after);
    expect_no_orphans(procs);
    expect_no_stale_shm(since);
}

TEST(Faults, CtrlCStopsEverythingAndCleansUp) {
    const std::time_t since = std::time(nullptr) - 1;
    const auto out = temp_dir("ctrlc");
    const pid_t launcher = start(paced_run(out), out / "log.txt");
    const auto procs = wait_for_processes(out);
    ASSERT_EQ(procs.size(), 6u);
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    // Ctrl-C in a terminal signals the whole foreground process group.
    ASSERT_EQ(kill(-launcher, SIGINT), 0);
    const int code = wait_for(launcher, 20.0);
    EXPECT_EQ(code, 130) << read_file(out / "log.txt");
    expect_no_orphans(procs);
    expect_no_stale_shm(since);
}

TEST(Faults, SigkilledLauncherTakesItsChildrenDown) {
    const std::time_t since = std::time(nullptr) - 1;
    const auto out = temp_dir("killlauncher");
    const pid_t launcher = start(paced_run(out), out / "log.txt");
    const auto procs = wait_for_processes(out);
    ASSERT_EQ(procs.size(), 6u);
    std::this_thread::sleep_for(std::chrono::milliseconds(1000));
    ASSERT_EQ(kill(launcher, SIGKILL), 0);
    wait_for(launcher, 5.0);
    bool all_gone = false;
    for (int i = 0; i < 300 && !all_gone; ++i) {
        all_gone = true;
        for (const auto& [n, pid] : procs) all_gone = all_gone && !alive(pid);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    EXPECT_TRUE(all_gone);
    // Children terminated cleanly (SIGTERM) and released their segments themselves.
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    expect_no_stale_shm(since);
}
