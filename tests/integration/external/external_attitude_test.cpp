// An external attitude filter of the user's own design (examples/attitude_filter: a complementary
// filter built against the INSTALLED gdnav package) replaces `nav_att` in a full paper scenario-#2 run (composed
// layout: the built-in members share one process, the filter is a process of its own; 500 s, GNSS lost at t = 100 s)
// and flies it. Its attitude and horizontal errors (nav_recorder's
// metrics.yaml) are printed next to those of the built-in EKF on the same seed — not asserted against the paper.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "math/rotation.hpp"
#include "metrics/run_record.hpp"
#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;
using gdnav::metrics::RunRecord;
using gdnav::metrics::Signal;

namespace {

using gdnav::math::kDeg;

// A DDS domain of this test's own (other external-member tests use 150-209).
int fresh_domain() { return 210 + static_cast<int>(getpid() % 20); }

void print_row(const char* what, const RunRecord& r) {
    std::printf("  %-36s %8.3f %8.3f %8.3f %8.3f %10.1f %8.2f\n", what, r[Signal::rot].mean / kDeg,
                std::fabs(r[Signal::rot].max) / kDeg, std::fabs(r[Signal::yaw].max) / kDeg,
                std::max(std::fabs(r[Signal::pitch].max), std::fabs(r[Signal::bank].max)) / kDeg,
                r[Signal::hor].final, r.hor_pct);
}

}  // namespace

TEST(ExternalAttitude, ComplementaryFilterReplacesNavAttAndFliesScenario2) {
    // Reference: the built-in nav_att on the same seed (direct layout: same bits as distributed, a few seconds).
    const fs::path ref = temp_dir("extatt-ref");
    const Result r0 = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--layout", "direct",
                           "--out", ref.string()},
                          120.0);
    ASSERT_EQ(r0.exit_code, 0) << r0.output;
    const RunRecord builtin = gdnav::metrics::read_run_record(ref / "metrics.yaml");

    // The run with nav_att outside: gdnav starts every other member, the example joins on the same domain.
    const fs::path out = temp_dir("extatt");
    const std::string domain = std::to_string(fresh_domain());
    const pid_t launcher = start({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--layout",
                                  "composed", "--external", "nav_att", "--domain", domain, "--out", out.string()},
                                 out.string() + ".run.log");
    const pid_t member = start({std::string(GDNAV_EXAMPLES_BIN) + "/gdnav-example-attitude", "--domain", domain},
                               out.string() + ".member.log");
    // 55 001 lockstep steps, each a round trip between two processes; the limit only catches a hung run.
    const int run_code = wait_for(launcher, 540.0);
    if (run_code == -1) {  // overrun: Ctrl-C the run (it stops its members and cleans /dev/shm)
        kill(-launcher, SIGINT);
        if (wait_for(launcher, 30.0) == -1) kill(-launcher, SIGKILL);
    }
    const int member_code = wait_for(member, 30.0);
    if (member_code == -1) kill(-member, SIGKILL);
    const std::string run_log = read_file(out.string() + ".run.log");
    const std::string member_log = read_file(out.string() + ".member.log");
    ASSERT_EQ(run_code, 0) << run_log << "\n--- member:\n" << member_log;
    EXPECT_EQ(member_code, 0) << member_log;
    EXPECT_NE(run_log.find("external member 'nav_att' joined"), std::string::npos) << run_log;
    EXPECT_NE(member_log.find("complementary filter: run completed"), std::string::npos) << member_log;
    // Every member stayed to the end (a member lost on the way would leave the figures below meaningless).
    EXPECT_EQ(run_log.find("declared dead"), std::string::npos) << run_log;

    const RunRecord ext = gdnav::metrics::read_run_record(out / "metrics.yaml");
    ASSERT_TRUE(ext.complete) << run_log;
    ASSERT_GT(ext.t_end_s, 499.0) << run_log;  // the whole 500 s of scenario #2 were flown and scored
    EXPECT_EQ(ext.samples, builtin.samples);

    std::printf("scenario #2, seed 1 (%.0f m flown after the GNSS loss at t = %.0f s):\n", ext.distance_m,
                ext.t_gnss_s);
    std::printf("  %-36s %8s %8s %8s %8s %10s %8s\n", "attitude filter", "att mean", "att max", "yaw max",
                "tilt max", "hor final", "hor");
    std::printf("  %-36s %8s %8s %8s %8s %10s %8s\n", "", "[deg]", "[deg]", "[deg]", "[deg]", "[m]", "[%]");
    print_row("built-in nav_att (EKF, direct)", builtin);
    print_row("external complementary (composed)", ext);
    RecordProperty("external_attitude_error_mean_deg", std::to_string(ext[Signal::rot].mean / kDeg));
    RecordProperty("external_attitude_error_max_deg", std::to_string(std::fabs(ext[Signal::rot].max) / kDeg));
    RecordProperty("external_horizontal_error_final_pct", std::to_string(ext.hor_pct));

    // Sanity bounds only (the filter is an example, not the paper's). Broken filters fail them by far: a filter
    // that stopped propagating, or held the alignment, would be off by the heading changes of the eight turns (tens
    // of degrees); a filter with a wrong correction sign or an unobserved gyro bias (0.2 deg/s per axis) drifts by
    // many degrees in 550 s. A working complementary filter stays within a degree or so (the tilt references
    // carry the gust accelerations), so 5 deg mean and 15 deg max are wide margins.
    EXPECT_LT(ext[Signal::rot].mean / kDeg, 5.0);
    EXPECT_LT(std::fabs(ext[Signal::rot].max) / kDeg, 15.0);
    // The external filter really was the one flying: its errors differ from the built-in EKF's.
    EXPECT_NE(ext[Signal::rot].mean, builtin[Signal::rot].mean);
    // The aircraft flew the mission with these attitudes: the position filter's dead reckoning stayed sane (the
    // built-in figure is ~1.5 % of the distance; a heading error of 5 deg alone would make ~9 %).
    EXPECT_LT(ext.hor_pct, 25.0);
}
