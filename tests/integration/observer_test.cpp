// An observer member (runtime::Component::observer; the live bridge is one) never holds a distributed run: it is
// out of the clock's barrier and reads with best-effort readers. The bridge's process is paused (SIGSTOP) for 2 s in
// the middle of the run, shorter than the member timeout: a barrier member that far behind would hold every other
// member within the window (64 steps) and never lose a step; the observer instead falls behind by more than its
// inbox (128 steps), gives those steps up (counted in its log line), catches up when it resumes, and the run
// completes, reproducible, nobody declared dead.
#include <gtest/gtest.h>

#include <signal.h>

#include <chrono>
#include <regex>
#include <thread>

#include <yaml-cpp/yaml.h>

#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

TEST(Observer, APausedLiveBridgeDoesNotHoldADistributedRun) {
    constexpr int kSteps = 8000;
    const int port = free_port();
    ASSERT_GT(port, 0);
    const fs::path out = temp_dir("observer");
    const fs::path log = out.parent_path() / (out.filename().string() + ".log");
    const pid_t run_pid = start({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--steps",
                                 std::to_string(kSteps), "--layout", "distributed", "--live", std::to_string(port), "--set",
                                 "run.member_timeout_s=5", "--out", out.string()},
                                log);
    // The run has started (the clock's line), then the bridge is paused for 2 s.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (read_file(log).find("all members ready") == std::string::npos) {
        ASSERT_TRUE(alive(run_pid)) << read_file(log);
        ASSERT_LT(std::chrono::steady_clock::now(), deadline) << read_file(log);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    const auto procs = read_processes(out);
    ASSERT_TRUE(procs.count("live")) << read_file(log);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    ASSERT_EQ(kill(procs.at("live"), SIGSTOP), 0);
    std::this_thread::sleep_for(std::chrono::seconds(2));
    ASSERT_EQ(kill(procs.at("live"), SIGCONT), 0);
    const int code = wait_for(run_pid, 180.0);
    const std::string text = read_file(log);
    ASSERT_EQ(code, 0) << text;

    std::smatch m;
    ASSERT_TRUE(std::regex_search(text, m, std::regex(R"(observer 'live': computed (\d+) of (\d+) steps, skipped (\d+))")))
        << text;
    const long computed = std::stol(m[1]), total = std::stol(m[2]), skipped = std::stol(m[3]);
    std::printf("observer 'live' paused 2 s: computed %ld of %ld steps, skipped %ld\n", computed, total, skipped);
    EXPECT_EQ(total, kSteps);
    EXPECT_EQ(computed + skipped, kSteps);
    EXPECT_GT(skipped, 128) << "the run waited for the paused bridge";
    EXPECT_GT(computed, 0);

    const YAML::Node summary = YAML::LoadFile((out / "clock_summary.yaml").string());
    EXPECT_TRUE(summary["completed"].as<bool>());
    EXPECT_EQ(summary["dead_members"].size(), 0u) << text;
    EXPECT_TRUE(summary["reproducible"].as<bool>()) << "an observer writes nothing: the run stays reproducible";
}
