// Failed runs of a batch (launch/batch/batch_failures): the run's record, the batch's failures.yaml, the Markdown of
// the report, and a failed run's metrics.yaml moved aside so that the run counts as missing.
#include "launch/batch/batch_failures.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include <yaml-cpp/yaml.h>

#include "launch/batch/batch_dir.hpp"
#include "temp_dir.hpp"

namespace gdnav::launch::batch {
namespace {

namespace fs = std::filesystem;

using test::write_text;

TEST(BatchFailures, LastLinesSkipBlankLinesAndKeepTheEnd) {
    gdnav::test::TempDir dir;
    write_text(dir.path() / "a.txt", "one\n\ntwo\nthree  \n\n");
    EXPECT_EQ(last_lines(dir.path() / "a.txt", 2), (std::vector<std::string>{"two", "three"}));
    EXPECT_EQ(last_lines(dir.path() / "a.txt", 10).size(), 3u);
    EXPECT_TRUE(last_lines(dir.path() / "missing", 3).empty());
}

TEST(BatchFailures, ARecordedFailureIsSummarisedAndItsMetricsMovedAside) {
    gdnav::test::TempDir dir;
    const fs::path run1 = dir.path() / "runs" / run_dir_name(1);
    const std::string cause =
        "[error] run failed: member nav_att (exit code 7), started by gdnav; its output is in runs/run_0001/logs/";
    write_text(run1 / "log.txt", "[info] starting\n" + cause + "\n");
    write_text(run1 / "logs" / "nav_att.log", "filter: cannot open table\n");
    write_text(run1 / "metrics.yaml", "complete: true\n");
    const RunFailure f = record_run_failure(run1, 1, 1);
    EXPECT_EQ(f.cause, cause);
    ASSERT_EQ(f.member_tails.size(), 1u);
    EXPECT_EQ(f.member_tails[0].first, "nav_att");
    EXPECT_FALSE(fs::exists(run1 / "metrics.yaml"));
    EXPECT_TRUE(fs::exists(run1 / "metrics.failed.yaml"));

    write_failures_summary(dir.path());
    const YAML::Node s = YAML::LoadFile((dir.path() / "failures.yaml").string());
    ASSERT_EQ(s["failed"].size(), 1u);
    EXPECT_EQ(s["failed"][0]["run"].as<int>(), 1);
    EXPECT_EQ(s["failed"][0]["dir"].as<std::string>(), "runs/run_0001");
    EXPECT_EQ(s["failed"][0]["exit_code"].as<int>(), 1);
    EXPECT_EQ(s["failed"][0]["member_logs"]["nav_att"][0].as<std::string>(), "filter: cannot open table");
    const auto back = read_run_failures(dir.path());
    ASSERT_EQ(back.size(), 1u);
    EXPECT_EQ(back[0].cause, f.cause);
    const std::string md = failures_markdown(back, "b");
    EXPECT_NE(md.find("### run 1: exit code 1"), std::string::npos) << md;
    EXPECT_NE(md.find("filter: cannot open table"), std::string::npos) << md;

    // The run made anew (a rerun removes its folder) and no failure left: no failures.yaml.
    fs::remove_all(run1);
    write_failures_summary(dir.path());
    EXPECT_FALSE(fs::exists(dir.path() / "failures.yaml"));
}

}  // namespace
}  // namespace gdnav::launch::batch
