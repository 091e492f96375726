// Issue 10: members that gdnav did not start. `gdnav run --external NAME` waits for them (clear error naming a
// missing one at the join timeout), the client library joins runs in the distributed and composed layouts, an external
// re-implementation of `control` built from the INSTALLED package gives bit-identical outputs, and a free-running
// external controller flies a real-time run (hardware-in-the-loop mode) with its lateness recorded.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <regex>
#include <thread>

#include <yaml-cpp/yaml.h>

#include "process_util.hpp"
#include "launch/shm_cleanup.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

const std::string kRecorded = "ImuSample,MagSample,AirSample,AtmSample,GnssSample,Truth,AirDataEstimate,"
                              "AttitudeEstimate,PositionEstimate,GuidanceTargets,ControlCommands";

std::string example(const std::string& name) { return std::string(GDNAV_EXAMPLES_BIN) + "/" + name; }

// A DDS domain of its own per run (the launcher's default derives one from its pid; the external member must know it).
int fresh_domain() {
    static int n = 0;
    return 150 + static_cast<int>((getpid() + n++) % 60);
}

void expect_no_orphans(const fs::path& out) {
    for (const auto& [name, pid] : read_processes(out)) EXPECT_FALSE(alive(pid)) << name << " (pid " << pid << ") still running";
}

using Pair = PairResult;

// `gdnav run ARGS --domain D --out OUT` (ARGS name the --external member) and the external member on domain D.
Pair run_with_external(std::vector<std::string> run_args, std::vector<std::string> member_argv, const fs::path& out,
                       double timeout_s) {
    const std::string domain = std::to_string(fresh_domain());
    run_args.insert(run_args.begin(), GDNAV_GDNAV_EXE);
    run_args.insert(run_args.end(), {"--domain", domain, "--out", out.string()});
    member_argv.insert(member_argv.end(), {"--domain", domain});
    return run_pair(run_args, member_argv, out, timeout_s);
}

}  // namespace

TEST(External, NobodyJoiningEndsTheRunWithAClearErrorNamingTheMember) {
    const auto out = temp_dir("ext-missing");
    const std::time_t since = std::time(nullptr) - 1;
    const Result r = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--layout", "distributed", "--external",
                          "nav_att", "--join-timeout", "3", "--domain", std::to_string(fresh_domain()), "--out",
                          out.string()},
                         60.0);
    EXPECT_EQ(r.exit_code, 5) << r.output;
    EXPECT_NE(r.output.find("waiting for external member(s) 'nav_att'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("external member 'nav_att' did not join within 3 s"), std::string::npos) << r.output;
    // Three seconds of joining, then the members hear ABORT: well within the start-up timeout.
    EXPECT_LT(r.wall_s, 20.0) << r.output;
    std::printf("missing external member: exit %d after %.1f s\n", r.exit_code, r.wall_s);
    expect_no_orphans(out);
    EXPECT_TRUE(gdnav::launch::stale_fastdds_shm(since).empty());
}

TEST(External, DirectLayoutRejectsExternalMembers) {
    const auto out = temp_dir("ext-direct");
    const Result r = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--layout", "direct", "--external",
                          "nav_att", "--out", out.string()},
                         30.0);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("external members need the lockstep clock"), std::string::npos) << r.output;
    // Bad names are one-line config errors too.
    const Result bad = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--external", "clock", "--out", out.string()}, 30.0);
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
    EXPECT_NE(bad.output.find("'clock' is the lockstep clock"), std::string::npos) << bad.output;
}

TEST(External, ExternalControlFromTheInstalledPackageIsBitIdenticalToTheBuiltIn) {
    // Reference: the all-built-in run (direct layout; layouts are bit-identical, tests/integration/runs/layouts_test.cpp).
    const auto ref = temp_dir("ext-ref");
    const Result r0 = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--layout", "direct",
                           "--steps", "20000", "--record", kRecorded, "--out", ref.string()},
                          120.0);
    ASSERT_EQ(r0.exit_code, 0) << r0.output;
    const auto expected = read_digests(ref);
    ASSERT_EQ(expected.size(), 11u) << r0.output;

    // Scenario #2 in the distributed layout with control outside, through the GNSS loss (t = 100 s at step 15 000)
    // and the first 50 s of the GNSS-denied mission.
    const auto out = temp_dir("ext-control");
    const Pair p = run_with_external({"run", "--scenario", "paper2", "--seed", "1", "--layout", "distributed",
                                      "--steps", "20000", "--record", kRecorded, "--external", "control"},
                                     {example("gdnav-example-control")}, out, 280.0);
    ASSERT_EQ(p.run_code, 0) << p.run_log << "\n--- member:\n" << p.member_log;
    EXPECT_EQ(p.member_code, 0) << p.member_log;
    EXPECT_NE(p.run_log.find("external member 'control' joined"), std::string::npos) << p.run_log;
    const auto got = read_digests(out);
    EXPECT_EQ(got, expected) << p.run_log;
    expect_no_orphans(out);
}

TEST(External, ExternalControlJoinsTheComposedLayout) {
    const auto ref = temp_dir("ext-ref-c");
    const Result r0 = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "2", "--layout", "direct",
                           "--steps", "3000", "--record", kRecorded, "--out", ref.string()},
                          60.0);
    ASSERT_EQ(r0.exit_code, 0) << r0.output;
    const auto out = temp_dir("ext-composed");
    const Pair p = run_with_external({"run", "--scenario", "paper2", "--seed", "2", "--layout", "composed", "--steps",
                                      "3000", "--record", kRecorded, "--external", "control", "--log-level", "debug"},
                                     {example("gdnav-example-control")}, out, 120.0);
    ASSERT_EQ(p.run_code, 0) << p.run_log << "\n--- member:\n" << p.member_log;
    EXPECT_EQ(p.member_code, 0) << p.member_log;
    EXPECT_EQ(read_digests(out), read_digests(ref)) << p.run_log;
    // The composed process reads over DDS only what the external member writes (docs/runtime.md, "Members: what a
    // step costs"): its members' other inputs come by hand-over, without a DDS reader of their own.
    std::smatch m;
    ASSERT_TRUE(std::regex_search(p.run_log, m, std::regex("read without DDS: ([^\n]*)"))) << p.run_log;
    const std::string dropped = m[1];
    for (const char* in : {"nav_att:gdnav/ImuSample", "nav_pos:gdnav/AttitudeEstimate", "nav_recorder:gdnav/Truth"})
        EXPECT_NE(dropped.find(in), std::string::npos) << in << " in: " << dropped;
    EXPECT_EQ(dropped.find("ControlCommands"), std::string::npos) << dropped;
}

// Issue 12 item 5 with an external member: a secure composed run (DDS Security, docs/deployment.md) with the
// installed package's control member joining under its own certificate gives the plain run's outputs; the same
// member without a certificate is never matched, so the run ends at the join timeout naming it.
TEST(External, ExternalControlJoinsASecureRunOnlyWithItsCertificate) {
    const auto ref = temp_dir("ext-ref-s");
    const Result r0 = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "2", "--layout", "direct",
                           "--steps", "2000", "--record", kRecorded, "--out", ref.string()},
                          60.0);
    ASSERT_EQ(r0.exit_code, 0) << r0.output;
    const fs::path pki = temp_dir("ext-pki") / "pki";
    const Result init = run({GDNAV_GDNAV_EXE, "pki", "init", pki.string(), "--scenario", "paper2"}, 60.0);
    ASSERT_EQ(init.exit_code, 0) << init.output;

    const auto out = temp_dir("ext-secure");
    const Pair p = run_with_external({"run", "--scenario", "paper2", "--seed", "2", "--layout", "composed", "--steps",
                                      "2000", "--record", kRecorded, "--external", "control", "--security",
                                      pki.string()},
                                     {example("gdnav-example-control"), "--security", pki.string()}, out, 120.0);
    ASSERT_EQ(p.run_code, 0) << p.run_log << "\n--- member:\n" << p.member_log;
    EXPECT_EQ(p.member_code, 0) << p.member_log;
    EXPECT_EQ(read_digests(out), read_digests(ref)) << p.run_log;

    const auto out2 = temp_dir("ext-uncertified");
    const Pair q = run_with_external({"run", "--scenario", "paper2", "--seed", "2", "--layout", "composed", "--steps",
                                      "2000", "--external", "control", "--join-timeout", "8", "--security",
                                      pki.string()},
                                     {example("gdnav-example-control"), "--startup-timeout", "10"}, out2, 60.0);
    EXPECT_NE(q.run_code, 0) << q.run_log;
    EXPECT_NE(q.run_log.find("control"), std::string::npos) << q.run_log;
    EXPECT_NE(q.member_code, 0) << q.member_log;
}

TEST(External, RealTimeHardwareInTheLoopWithAFreeRunningController) {
    // 30 s of scenario #2 (t = -50 ... -20 s) paced to wall time; the external controller is free-running: the
    // physics uses the newest command it has (zero-order hold) and records how late each one was.
    const auto out = temp_dir("ext-hil");
    const std::uint64_t steps = 3001;
    const Pair p = run_with_external({"run", "--scenario", "paper2", "--seed", "1", "--layout", "distributed",
                                      "--steps", std::to_string(steps), "--realtime", "1", "--external", "control"},
                                     {example("gdnav-example-control"), "--free-running"}, out, 150.0);
    ASSERT_EQ(p.run_code, 0) << p.run_log << "\n--- member:\n" << p.member_log;
    EXPECT_EQ(p.member_code, 0) << p.member_log;
    const YAML::Node summary = YAML::LoadFile((out / "clock_summary.yaml").string());
    EXPECT_FALSE(summary["reproducible"].as<bool>());
    const double wall = summary["wall_s"].as<double>();
    const double simulated = static_cast<double>(steps - 1) * 0.01;
    std::printf("real-time run: %.0f s simulated in %.3f s of wall time (%.2f %% off)\n", simulated, wall,
                100.0 * (wall - simulated) / simulated);
    // The acceptance figure is "real time within 1 %" (printed above; measured on a quiet machine, see
    // docs/external.md). Tests do not assert on wall time; what is asserted is that pacing works at all: not run as
    // fast as possible (~10 s here), not a multiple of real time. A loaded machine stretches the run a little.
    EXPECT_GT(wall, simulated);
    EXPECT_LT(wall, 1.25 * simulated);

    // Lateness of the controller's commands as flight_physics used them.
    const fs::path lat = out / "lateness" / "flight_physics.yaml";
    ASSERT_TRUE(fs::exists(lat)) << p.run_log;
    const YAML::Node in = YAML::LoadFile(lat.string())["inputs"]["gdnav/ControlCommands"];
    ASSERT_TRUE(in) << read_file(lat).substr(0, 500);
    const auto used = in["used"].as<std::uint64_t>();
    const auto none = in["no_sample"].as<std::uint64_t>();
    const auto misses = in["misses"].as<std::uint64_t>();
    const double mean = in["mean_steps"].as<double>();
    const auto worst = in["max_steps"].as<std::uint64_t>();
    std::printf("ControlCommands at flight_physics: %llu steps used a command, %llu had none yet, lateness mean %.3f "
                "steps, max %llu, deadline misses %llu (%.2f %%)\n",
                static_cast<unsigned long long>(used), static_cast<unsigned long long>(none), mean,
                static_cast<unsigned long long>(worst), static_cast<unsigned long long>(misses),
                100.0 * static_cast<double>(misses) / static_cast<double>(std::max<std::uint64_t>(used, 1)));
    EXPECT_EQ(used + none, steps);
    EXPECT_EQ(in["per_step"].size(), steps);
    // Sane: commands arrive from the first seconds on (the first one needs the first estimates), every step is
    // accounted for, and the controller keeps up on average (a quiet machine gives a mean near 0; a loaded one, a few
    // steps with bursts up to ~1.5 s); a controller that stopped answering would show thousands of steps.
    EXPECT_GT(used, steps * 9 / 10);
    EXPECT_LT(mean, 10.0);
    EXPECT_LT(worst, 500u);
    EXPECT_NE(p.run_log.find("free-running input 'gdnav/ControlCommands'"), std::string::npos) << p.run_log;
    // The aircraft flew: the clock completed and nobody was declared dead.
    EXPECT_EQ(p.run_log.find("declared dead"), std::string::npos) << p.run_log;
}
