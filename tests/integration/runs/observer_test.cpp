// An observer member (framework::Component::observer; the live bridge is one) never holds a distributed run: it is
// out of the clock's barrier and reads with best-effort readers. The bridge's process is paused (SIGSTOP) from the
// start of the run until the clock has ended, within the member timeout: a barrier member paused like that would hold
// every other member within the window (64 steps) and the clock could not end. The bridge, resumed, computes what
// its socket buffers and inbox kept and counts the steps it gave up or did not reach (its log line), and the run
// completes, reproducible, nobody declared dead.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

// The nice value of every thread of process `pid` (/proc/PID/task/TID/stat, field 19).
std::vector<int> thread_nices(pid_t pid) {
    std::vector<int> v;
    for (const auto& e : fs::directory_iterator("/proc/" + std::to_string(pid) + "/task")) {
        const std::string stat = read_file(e.path() / "stat");
        std::istringstream rest(stat.substr(stat.rfind(')') + 2));  // after "(comm) ": field 3 onwards
        std::string field;
        for (int i = 3; i <= 19 && rest >> field; ++i) {
        }
        v.push_back(std::stoi(field));
    }
    return v;
}

}  // namespace

TEST(Observer, APausedLiveBridgeDoesNotHoldADistributedRun) {
    constexpr int kSteps = 8000;
    const int port = free_port();
    ASSERT_GT(port, 0);
    const fs::path out = temp_dir("observer");
    const fs::path log = out.parent_path() / (out.filename().string() + ".log");
    const pid_t run_pid = start({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--steps",
                                 std::to_string(kSteps), "--layout", "distributed", "--live", std::to_string(port), "--set",
                                 "run.member_timeout_s=20", "--out", out.string()},
                                log);
    // The run has started (the clock's line); the bridge is paused below, until the clock has ended.
    ASSERT_TRUE(wait_for_log(run_pid, log, "all members ready", 120.0)) << read_file(log);
    const auto procs = read_processes(out);
    ASSERT_TRUE(procs.count("live")) << read_file(log);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    // A process of observers only runs at run.observer_nice (default 19), every thread of it but one; the barrier members
    // keep the priority they were started with (this test's).
    const int own = getpriority(PRIO_PROCESS, 0);
    const std::vector<int> live_nice = thread_nices(procs.at("live")), att_nice = thread_nices(procs.at("nav_att"));
    ASSERT_GE(live_nice.size(), 2u);
    // All but one: the heartbeat pulse keeps the priority, so that a starved bridge stays alive for the clock.
    EXPECT_EQ(std::count(live_nice.begin(), live_nice.end(), std::max(own, 19)),
              static_cast<long>(live_nice.size()) - (own < 19 ? 1 : 0))
        << "the threads of the live bridge";
    if (own < 19) {
        EXPECT_EQ(std::count(live_nice.begin(), live_nice.end(), own), 1) << "the bridge's pulse thread";
    }
    for (int n : att_nice) EXPECT_EQ(n, own) << "a thread of nav_att";
    ASSERT_TRUE(procs.count("clock")) << read_file(log);
    ASSERT_EQ(kill(procs.at("live"), SIGSTOP), 0);
    // Paused until the clock has ended, at most 18 s (within the 20-s member timeout, so never declared dead).
    const auto paused_until = std::chrono::steady_clock::now() + std::chrono::seconds(18);
    while (alive(procs.at("clock")) && std::chrono::steady_clock::now() < paused_until)
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    const bool clock_ended = !alive(procs.at("clock"));
    ASSERT_EQ(kill(procs.at("live"), SIGCONT), 0);
    EXPECT_TRUE(clock_ended) << "the run did not end while the bridge was paused: it waited for the observer";
    const int code = wait_for(run_pid, 180.0);
    const std::string text = read_file(log);
    ASSERT_EQ(code, 0) << text;

    std::smatch m;
    ASSERT_TRUE(std::regex_search(
        text, m,
        std::regex(R"(observer 'live': computed (\d+) of (\d+) steps, (?:skipped (\d+)|none skipped)(, (\d+) not reached before the end)?)")))
        << text;
    const long computed = std::stol(m[1]), total = std::stol(m[2]), skipped = m[3].matched ? std::stol(m[3]) : 0;
    // On an over-committed machine the bridge, at nice 19, may still be behind when the run ends: those steps are
    // counted apart, and the run did not wait for them either.
    const long unreached = m[5].matched ? std::stol(m[5]) : 0;
    std::printf("observer 'live' paused until the clock ended: computed %ld of %ld steps, skipped %ld, not reached %ld\n",
                computed, total, skipped, unreached);
    EXPECT_EQ(total, kSteps);
    EXPECT_EQ(computed + skipped + unreached, kSteps);
    EXPECT_GT(computed, 0);

    const YAML::Node summary = YAML::LoadFile((out / "clock_summary.yaml").string());
    EXPECT_TRUE(summary["completed"].as<bool>());
    EXPECT_EQ(summary["dead_members"].size(), 0u) << text;
    EXPECT_TRUE(summary["reproducible"].as<bool>()) << "an observer writes nothing: the run stays reproducible";
}
