// Members started by gdnav (`--member NAME=COMMAND`, run.members) in Monte Carlo batches, with the C++ example
// attitude filter (examples/attitude_filter, built from the installed package) replacing nav_att:
//   * a 3-run batch with --jobs 2 in the composed and in the distributed layout: every run complete, the member's
//     command and the SHA-256 of its executable in processes.yaml, its output in logs/nav_att.log, and the two
//     batches' metrics.yaml byte-identical (the lockstep makes the layouts the same bits);
//   * a member that exits non-zero in run 1 only: runs 0 and 2 complete, run 1 failed and named with its last log
//     lines in failures.yaml and the report; the same command again (the member fixed) reruns only run 1;
//   * the direct layout, and a command that cannot be found, are refused with one line before anything starts.
// The batches pick their DDS domains themselves (launch/domain_lock.hpp).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "launch/member_process.hpp"
#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

// 3000 steps of 10 ms from t0 = -50 s: a few seconds per run, long enough for the filter to converge.
const std::string kSteps = "3000";

std::string example() { return std::string(GDNAV_EXAMPLES_BIN) + "/gdnav-example-attitude"; }

fs::path run_path(const fs::path& batch_dir, int i) { return run_dir(batch_dir, i); }

bool complete(const fs::path& metrics) {
    return read_file(metrics).find("\ncomplete: true\n") != std::string::npos;
}

std::vector<std::string> batch(const std::string& layout, const std::string& member, const fs::path& out) {
    return {kExe,    "montecarlo", "--scenario", "2",      "--runs",       "3",       "--jobs",
            "2",     "--seed",     "3",          "--steps", kSteps,        "--layout", layout,
            "--member", "nav_att=" + member, "--no-figures", "--out", out.string()};
}

void expect_complete_batch(const fs::path& dir, const Result& r) {
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("3/3 runs done, 0 failed"), std::string::npos) << r.output;
    for (int i = 0; i < 3; ++i) {
        const fs::path run = run_path(dir, i);
        EXPECT_TRUE(complete(run / "metrics.yaml")) << i;
        EXPECT_NE(read_file(run / "logs" / "nav_att.log").find("complementary filter: run completed"),
                  std::string::npos)
            << read_file(run / "logs" / "nav_att.log");
        const std::string procs = read_file(run / "processes.yaml");
        EXPECT_NE(procs.find("nav_att: {pid: "), std::string::npos) << procs;
        EXPECT_NE(procs.find("sha256: " + gdnav::launch::sha256_of_file(example())), std::string::npos) << procs;
        EXPECT_EQ(read_file(run / "log.txt").find("declared dead"), std::string::npos) << read_file(run / "log.txt");
    }
}

}  // namespace

TEST(MemberBatch, TheCxxExampleInComposedAndDistributedBatchesGivesTheSameBits) {
    const fs::path composed = temp_dir("members_composed");
    const Result c = run(batch("composed", example(), composed), 240.0);
    expect_complete_batch(composed, c);
    const fs::path distributed = temp_dir("members_distributed");
    const Result d = run(batch("distributed", example(), distributed), 360.0);
    expect_complete_batch(distributed, d);
    for (int i = 0; i < 3; ++i) {
        const std::string m = read_file(run_path(composed, i) / "metrics.yaml");
        EXPECT_FALSE(m.empty());
        EXPECT_EQ(m, read_file(run_path(distributed, i) / "metrics.yaml")) << "run " << i;
    }
    // Runs differ from each other (their draws do), so the equality means something.
    EXPECT_NE(read_file(run_path(composed, 0) / "metrics.yaml"), read_file(run_path(composed, 1) / "metrics.yaml"));
}

TEST(MemberBatch, AMemberFailingInRunOneFailsOnlyThatRunAndTheRerunCompletesIt) {
    const fs::path dir = temp_dir("members_fail");
    const fs::path tools = temp_dir("members_fail_tools");
    const fs::path wrapper = tools / "flaky_member.sh";
    // Fails in run 1 until the file `fixed` exists beside it; else the real member, with its arguments.
    std::ofstream(wrapper) << "#!/bin/sh\n"
                              "if [ \"$GDNAV_RUN\" = 1 ] && [ ! -e \"$(dirname \"$0\")/fixed\" ]; then\n"
                              "  echo \"flaky member: giving up in run $GDNAV_RUN on domain $GDNAV_DOMAIN\" >&2\n"
                              "  exit 7\n"
                              "fi\n"
                              "exec " + example() + " \"$@\"\n";
    chmod(wrapper.c_str(), 0755);
    const auto cmd = batch("composed", wrapper.string(), dir);
    const Result r = run(cmd, 240.0);
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_TRUE(complete(run_path(dir, 0) / "metrics.yaml"));
    EXPECT_TRUE(complete(run_path(dir, 2) / "metrics.yaml"));
    EXPECT_FALSE(fs::exists(run_path(dir, 1) / "metrics.yaml"));
    const std::string failures = read_file(dir / "failures.yaml");
    EXPECT_NE(failures.find("run: 1\n"), std::string::npos) << failures;
    EXPECT_EQ(failures.find("run: 0\n"), std::string::npos) << failures;
    EXPECT_NE(failures.find("member nav_att (exit code 7)"), std::string::npos) << failures;
    EXPECT_NE(failures.find("flaky member: giving up in run 1"), std::string::npos) << failures;
    const std::string tables = read_file(dir / "report" / "tables.md");
    EXPECT_NE(tables.find("failed runs (last log lines at the end): 1 (exit code 1"), std::string::npos) << tables;
    EXPECT_NE(tables.find("### run 1: exit code 1"), std::string::npos) << tables;

    std::ofstream(tools / "fixed") << "1\n";
    const Result again = run(cmd, 240.0);
    ASSERT_EQ(again.exit_code, 0) << again.output;
    EXPECT_NE(again.output.find("3 complete runs (1 new, 2 skipped), 0 failed"), std::string::npos) << again.output;
    EXPECT_TRUE(complete(run_path(dir, 1) / "metrics.yaml"));
    EXPECT_FALSE(fs::exists(dir / "failures.yaml"));
    EXPECT_EQ(read_file(dir / "report" / "tables.md").find("failed runs"), std::string::npos);
}

TEST(MemberRun, DirectLayoutAndAMissingCommandAreRefusedBeforeAnythingStarts) {
    const fs::path out = temp_dir("members_refused");
    const Result direct = run({kExe, "run", "--scenario", "paper2", "--layout", "direct", "--steps", "10", "--member",
                               "nav_att=" + example(), "--out", out.string()},
                              60.0);
    EXPECT_EQ(direct.exit_code, 2) << direct.output;
    EXPECT_NE(direct.output.find("key 'run.members.nav_att': a process member needs the lockstep clock"),
              std::string::npos)
        << direct.output;
    EXPECT_FALSE(fs::exists(out / "processes.yaml"));
    const Result missing = run({kExe, "run", "--scenario", "paper2", "--layout", "composed", "--steps", "10",
                                "--domain", "161", "--member", "nav_att=gdnav-no-such-member --x", "--out",
                                out.string()},
                               60.0);
    EXPECT_EQ(missing.exit_code, 2) << missing.output;
    EXPECT_NE(missing.output.find("key 'run.members.nav_att.command': 'gdnav-no-such-member' is not an executable"),
              std::string::npos)
        << missing.output;
    EXPECT_FALSE(fs::exists(out / "processes.yaml"));
    const fs::path mc = temp_dir("members_refused_mc");
    const Result batch_direct = run(batch("direct", example(), mc), 60.0);
    EXPECT_EQ(batch_direct.exit_code, 2) << batch_direct.output;
    EXPECT_NE(batch_direct.output.find("a process member needs the lockstep clock"), std::string::npos)
        << batch_direct.output;
    EXPECT_FALSE(fs::exists(mc / "runs"));
}
