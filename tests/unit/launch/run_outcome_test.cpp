// The closing line of `gdnav run` (launch/run_outcome.hpp): the first cause of a failed run, and each member a
// completed run went on without, from clock_summary.yaml and the processes' ends.
#include "launch/run_outcome.hpp"

#include <fstream>

#include <gtest/gtest.h>

#include "temp_dir.hpp"

namespace gdnav::launch {
namespace {

TEST(RunOutcome, FailedRunNamesTheClocksReasonAndTheExitCode) {
    test::TempDir t;
    const auto file = t.path() / "clock_summary.yaml";
    // As the clock writes it: reasons double-quoted by the YAML emitter (a quote and a backslash inside).
    std::ofstream(file) << "completed: false\nsteps_done: 0\nabort_reason: \"external member 'nav_att' did not join "
                           "within 10 s (DDS domain 9, run id 0) \\\"x\\\\y\\\"\"\ndead_members:\n"
                           "rejoined_members: []\nreproducible: true\n";
    const ClockSummary s = read_clock_summary(file);
    ASSERT_TRUE(s.found);
    EXPECT_EQ(failed_run_line(5, s, {"flight_physics (exit code 1)"}),
              "run failed (exit code 5): external member 'nav_att' did not join within 10 s (DDS domain 9, run id 0) "
              "\"x\\y\"");
}

TEST(RunOutcome, WithoutTheClocksReasonTheFirstFailedProcessIsTheCause) {
    test::TempDir t;
    const ClockSummary none = read_clock_summary(t.path() / "missing.yaml");
    EXPECT_FALSE(none.found);
    EXPECT_EQ(failed_run_line(137, none, {"clock (killed by signal 9)", "nav_pos (exit code 4)"}),
              "run failed (exit code 137): process clock (killed by signal 9)");
    EXPECT_EQ(failed_run_line(1, none, {}), "run failed (exit code 1): the clock ended with exit code 1");
    std::ofstream(t.path() / "bad.yaml") << "completed: [\n";
    EXPECT_FALSE(read_clock_summary(t.path() / "bad.yaml").found);
}

TEST(RunOutcome, CompletedRunNamesEachMemberItWentOnWithoutOnce) {
    test::TempDir t;
    const auto file = t.path() / "clock_summary.yaml";
    std::ofstream(file) << "completed: true\ndead_members:\n"
                           "  - {name: nav_att, step: 300, reason: \"it reported: member 'nav_att' failed at step 300 "
                           "(t = -47.00 s): Python exception in the step callback: ZeroDivisionError: x\"}\n"
                           "  - {name: nav_pos, step: 12}\n";
    const ClockSummary s = read_clock_summary(file);
    ASSERT_EQ(s.dead.size(), 2u);
    EXPECT_EQ(s.dead[1].reason, "");  // a summary of a clock that recorded no reasons
    EXPECT_EQ(completed_run_line(s, {"nav_pos (exit code 1)", "live (killed by signal 6)"}, "out/x"),
              "run completed without: nav_att (declared dead at step 300: it reported: member 'nav_att' failed at step "
              "300 (t = -47.00 s): Python exception in the step callback: ZeroDivisionError: x), nav_pos (declared "
              "dead at step 12), live (killed by signal 6); results in out/x");
    EXPECT_EQ(completed_run_line(ClockSummary{}, {}, "out/y"), "run completed; results in out/y");
}

}  // namespace
}  // namespace gdnav::launch
