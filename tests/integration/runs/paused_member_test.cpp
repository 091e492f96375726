// A barrier member whose process gets no CPU for a while (a loaded machine, a debugger; here SIGSTOP) for less than
// run.member_timeout_s is waited for, not lost: the other members stop within the window, the member resumes, and the
// run completes with every member and the same recorded topics as a run nobody paused. The DDS participant lease
// (config/dds/gdnav_profiles.xml) must outlast the pause: with the former 3-s lease a 5-s pause unmatched the
// member's endpoints in its peers, they never matched again, and the member was declared dead 20 s later
// (docs/runtime.md, "Participant lease").
#include <gtest/gtest.h>

#include <signal.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

constexpr int kSteps = 3000;

// A distributed run of scenario #2 (seed 1, kSteps steps, every topic recorded with its digest), member timeout 20 s,
// paced at 5x real time so that the pause falls inside it; its own DDS domain.
std::vector<std::string> run_argv(const fs::path& out, int domain) {
    return {GDNAV_GDNAV_EXE, "run",      "--scenario", "paper2", "--seed", "1", "--steps", std::to_string(kSteps),
            "--layout",      "distributed", "--realtime", "5",    "--domain", std::to_string(domain),
            "--record",      "all",         "--set",      "run.member_timeout_s=20", "--out", out.string()};
}

int domain_of_this_test() { return 160 + static_cast<int>(getpid() % 20); }

}  // namespace

TEST(PausedMember, AMemberPausedForFiveSecondsWithinItsTimeoutIsWaitedForNotLost) {
    const fs::path out = temp_dir("paused");
    const fs::path log = out.parent_path() / (out.filename().string() + ".log");
    const pid_t run_pid = start(run_argv(out, domain_of_this_test()), log);
    ASSERT_TRUE(wait_for_log(run_pid, log, "all members ready", 120.0)) << read_file(log);
    const auto procs = read_processes(out);
    ASSERT_TRUE(procs.count("nav_att")) << read_file(log);
    std::this_thread::sleep_for(std::chrono::seconds(1));
    ASSERT_EQ(kill(procs.at("nav_att"), SIGSTOP), 0);
    std::this_thread::sleep_for(std::chrono::seconds(5));
    // The run (6 s of wall time at 5x) was still going when the member resumed: the pause happened inside it.
    const std::string at_resume = read_file(log);
    ASSERT_EQ(kill(procs.at("nav_att"), SIGCONT), 0);
    EXPECT_EQ(at_resume.find("run complete"), std::string::npos) << at_resume;

    const int code = wait_for(run_pid, 120.0);
    if (code == -1) kill(run_pid, SIGINT);
    const std::string text = read_file(log);
    ASSERT_EQ(code, 0) << text;
    EXPECT_EQ(text.find("declared dead"), std::string::npos) << text;
    EXPECT_EQ(text.find("run completed without"), std::string::npos) << text;
    const std::string summary = read_file(out / "clock_summary.yaml");
    EXPECT_NE(summary.find("steps_done: " + std::to_string(kSteps)), std::string::npos) << summary;
    EXPECT_NE(summary.find("reproducible: true"), std::string::npos) << summary;

    // The same run without a pause records the same bits.
    const fs::path ref = temp_dir("paused-ref");
    const Result r = run(run_argv(ref, domain_of_this_test()), 120.0);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto paused = read_digests(out), plain = read_digests(ref);
    ASSERT_FALSE(plain.empty());
    EXPECT_EQ(paused, plain);
}
