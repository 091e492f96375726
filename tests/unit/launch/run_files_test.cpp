// The files of a finished batch run (launch/batch/run_files.hpp): recorded when the run ends, any later change named.
#include "launch/batch/run_files.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "temp_dir.hpp"

namespace gdnav::launch::batch {
namespace {

namespace fs = std::filesystem;

using test::write_text;

// A run folder with results, a log and a recording.
fs::path make_run(const fs::path& root) {
    const fs::path run = root / "run_0003";
    write_text(run / "metrics.yaml", "complete: true\n");
    write_text(run / "run.h5", std::string(4096, 'x'));
    write_text(run / "record" / "run.mcap", "mcap");
    write_text(run / "log.txt", "a line\n");
    write_text(run / "logs" / "clock.log", "a line\n");
    return run;
}

TEST(RunFiles, AnUntouchedRunHasNoDamage) {
    const test::TempDir t;
    const fs::path run = make_run(t.path());
    write_run_files(run);
    EXPECT_EQ(run_files_damage(run, true), "");
    // The logs are diagnostics, not results: they may grow or go.
    write_text(run / "log.txt", "a line\nanother\n");
    fs::remove_all(run / "logs");
    EXPECT_EQ(run_files_damage(run, true), "");
}

TEST(RunFiles, ATruncatedFileIsNamedWithBothSizes) {
    const test::TempDir t;
    const fs::path run = make_run(t.path());
    write_run_files(run);
    fs::resize_file(run / "run.h5", 1000);
    EXPECT_EQ(run_files_damage(run, false), "run.h5 has 1000 bytes, 4096 when the run ended");
}

TEST(RunFiles, AMissingOrChangedFileIsNamed) {
    const test::TempDir t;
    const fs::path run = make_run(t.path());
    write_run_files(run);
    write_text(run / "record" / "run.mcap", "MCAP");  // same size, other bytes: only the digest sees it
    EXPECT_EQ(run_files_damage(run, false), "");
    EXPECT_EQ(run_files_damage(run, true), "record/run.mcap differs from the file the run wrote (digest)");
    fs::remove(run / "metrics.yaml");
    EXPECT_EQ(run_files_damage(run, true), "metrics.yaml is missing");
}

TEST(RunFiles, ARunWithoutItsListDidNotEndWell) {
    const test::TempDir t;
    const fs::path run = make_run(t.path());
    EXPECT_EQ(run_files_damage(run, true), "files.yaml is missing (the run did not end well)");
}

}  // namespace
}  // namespace gdnav::launch::batch
