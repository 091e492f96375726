// A full disk and a damaged batch say so (docs/runtime.md "Exit codes", docs/montecarlo.md "Damaged runs and a full
// disk"):
//   * a run recording onto a tiny file system ends with exit code 6 and, on its last line, the file and the OS error;
//     no HDF5 diagnostic stack; no metrics.yaml or clock_summary.yaml claiming a complete run (three layouts);
//   * a batch on a full disk stops after the first such run, and completes with the same command once there is room;
//   * a batch with one run's run.h5 truncated and another's metrics.yaml deleted: gdnav report names the damaged run
//     in one line; the same montecarlo command reruns both, and the batch is then byte-identical to an undamaged one.
// The tiny file system is a tmpfs the test mounts (root); where mounting is not allowed, a file size limit
// (RLIMIT_FSIZE through prlimit, SIGXFSZ ignored) stands in for it and the parts that need free space afterwards are
// skipped.
#include <gtest/gtest.h>
#include <sys/mount.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

std::string last_line(const std::string& text) {
    std::istringstream in(text);
    std::string line, last;
    while (std::getline(in, line))
        if (!line.empty()) last = line;
    return last;
}

bool claims_complete(const fs::path& run_dir) {
    const fs::path m = run_dir / "metrics.yaml";
    return fs::exists(m) && read_file(m).find("\ncomplete: true\n") != std::string::npos;
}

// A small file system at a fresh folder: a tmpfs of `bytes` when this process may mount (not with
// GDNAV_TEST_NO_MOUNT=1, which tries the other way), else a plain folder where command() limits the size of every
// file a process writes to `file_limit` bytes.
class TinyDisk {
public:
    TinyDisk(const std::string& name, std::size_t bytes, std::size_t file_limit)
        : dir_(temp_dir(name)), limit_(file_limit) {
        const char* no_mount = std::getenv("GDNAV_TEST_NO_MOUNT");
        mounted_ = !(no_mount && std::string(no_mount) == "1") &&
                   ::mount("tmpfs", dir_.c_str(), "tmpfs", 0, ("size=" + std::to_string(bytes)).c_str()) == 0;
    }
    ~TinyDisk() {
        if (mounted_) ::umount2(dir_.c_str(), MNT_DETACH);
    }
    TinyDisk(const TinyDisk&) = delete;
    TinyDisk& operator=(const TinyDisk&) = delete;
    [[nodiscard]] const fs::path& dir() const { return dir_; }
    [[nodiscard]] bool mounted() const { return mounted_; }
    // Room again (tmpfs only): the file system grows to `bytes`.
    bool grow(std::size_t bytes) {
        return mounted_ && ::mount("tmpfs", dir_.c_str(), "tmpfs", MS_REMOUNT,
                                   ("size=" + std::to_string(bytes)).c_str()) == 0;
    }
    // ARGV, under a file size limit when the folder is not a small file system of its own.
    [[nodiscard]] std::vector<std::string> command(std::vector<std::string> argv) const {
        if (mounted_) return argv;
        std::vector<std::string> wrapped{"/bin/sh", "-c", "trap '' XFSZ; exec prlimit --fsize=" +
                                                              std::to_string(limit_) + " -- \"$@\"",
                                         "sh"};
        wrapped.insert(wrapped.end(), argv.begin(), argv.end());
        return wrapped;
    }

private:
    fs::path dir_;
    bool mounted_{false};
    std::size_t limit_{0};
};

const std::regex kRefused(R"(cannot write \S+/run\.h5: (No space left on device|File too large))");

}  // namespace

TEST(FullDisk, ARunThatCannotWriteSaysWhichFileAndWhyOnItsLastLineInEveryLayout) {
    for (const std::string layout : {"direct", "composed", "distributed"}) {
        TinyDisk disk("full-disk-" + layout, 400 * 1024, 400 * 1024);
        const fs::path out = disk.dir() / "run";
        const Result r = run(disk.command({kExe, "run", "--scenario", "paper2", "--layout", layout, "--steps", "30000",
                                           "--out", out.string()}),
                             240.0);
        SCOPED_TRACE(layout + (disk.mounted() ? " (tmpfs)" : " (file size limit)"));
        EXPECT_EQ(r.exit_code, 6) << r.output;
        const std::string last = last_line(r.output);
        EXPECT_NE(last.find("run failed (exit code 6)"), std::string::npos) << last;
        EXPECT_TRUE(std::regex_search(last, kRefused)) << last;
        // HDF5's own diagnostic stack is not printed; the whole output stays short.
        EXPECT_EQ(r.output.find("HDF5-DIAG"), std::string::npos) << r.output;
        EXPECT_LT(count_of(r.output, "\n"), 40u) << r.output;
        // Nothing claims a complete run: no complete metrics.yaml, and no clock_summary.yaml cut short.
        EXPECT_FALSE(claims_complete(out));
        if (fs::exists(out / "clock_summary.yaml")) {
            const std::string s = read_file(out / "clock_summary.yaml");
            EXPECT_NE(s.find("completed: false"), std::string::npos) << s;
            EXPECT_NE(s.find("reproducible:"), std::string::npos) << s;  // written whole
        }
    }
}

TEST(FullDisk, ABatchStopsAfterTheFirstRunThatCannotWriteAndResumesWhenThereIsRoom) {
    // Room for two runs' files (run.h5 of 16 000 steps: 0.56 MB); or files limited below one run.h5.
    TinyDisk disk("full-disk-batch", 1536 * 1024, 400 * 1024);
    const fs::path out = disk.dir() / "batch";
    const std::vector<std::string> mc{kExe,      "montecarlo", "--scenario", "2",  "--runs", "4",      "--jobs",
                                      "1",       "--steps",    "16000",      "--layout", "direct", "--seed",
                                      "1",       "--no-report", "--out",      out.string()};
    const Result r = run(disk.command(mc), 300.0);
    EXPECT_EQ(r.exit_code, 6) << r.output;
    EXPECT_EQ(count_of(r.output, "no new run is started"), 1u) << r.output;  // one run failed, then none started
    EXPECT_NE(last_line(r.output).find("montecarlo: stopped: a run could not write its files"), std::string::npos)
        << r.output;
    int started = 0;
    for (int i = 0; i < 4; ++i) started += fs::exists(out / "runs" / ("run_000" + std::to_string(i)) / "run.yaml");
    EXPECT_LT(started, 4) << r.output;
    if (!disk.grow(64u << 20)) GTEST_SKIP() << "no tmpfs to grow: the resume is checked by DamagedBatch below";
    const Result again = run(mc, 300.0);
    ASSERT_EQ(again.exit_code, 0) << again.output;
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(claims_complete(out / "runs" / ("run_000" + std::to_string(i)))) << i;
}

TEST(DamagedBatch, ATruncatedRunAndAMissingMetricsAreNamedAndRunAgainByTheSameCommand) {
    const fs::path dir = temp_dir("damaged-batch");
    const fs::path out = dir / "batch", ref = dir / "undamaged";
    const std::vector<std::string> mc{kExe,   "montecarlo", "--scenario", "2",     "--runs",   "3",
                                      "--jobs", "2",        "--steps",    "16000", "--layout", "direct",
                                      "--seed", "1",        "--no-report", "--out", out.string()};
    ASSERT_EQ(run(mc, 300.0).exit_code, 0);
    fs::copy(out, ref, fs::copy_options::recursive);
    const fs::path run1 = out / "runs" / "run_0001", run2 = out / "runs" / "run_0002";
    fs::resize_file(run1 / "run.h5", 1000);
    fs::remove(run2 / "metrics.yaml");

    // gdnav report: one line naming the damaged run, no traceback.
    const Result rep = run({kExe, "report", out.string(), "--no-review"}, 240.0);
    EXPECT_NE(rep.exit_code, 0) << rep.output;
    EXPECT_EQ(rep.output.find("Traceback"), std::string::npos) << rep.output;
    const std::string named = last_line(rep.output);
    EXPECT_NE(named.find("run 1 (" + run1.string() + ") is damaged: run.h5 has 1000 bytes"), std::string::npos)
        << rep.output;

    // The same montecarlo command says why run 1 runs again, reruns it and run 2, and skips run 0.
    const Result again = run(mc, 300.0);
    ASSERT_EQ(again.exit_code, 0) << again.output;
    EXPECT_NE(again.output.find("run 1 (" + run1.string() + ") is damaged: run.h5 has 1000 bytes"), std::string::npos)
        << again.output;
    EXPECT_NE(again.output.find("3 complete runs (2 new, 1 skipped)"), std::string::npos) << again.output;
    for (const char* run_name : {"run_0000", "run_0001", "run_0002"})
        for (const char* file : {"metrics.yaml", "run.h5", "drawn_scenario.yaml"}) {
            const fs::path a = out / "runs" / run_name / file, b = ref / "runs" / run_name / file;
            EXPECT_TRUE(read_file(a) == read_file(b)) << a << " differs from the undamaged batch's";
        }
    EXPECT_EQ(run({kExe, "report", out.string(), "--no-figures"}, 240.0).exit_code, 0);
}

TEST(FullDisk, AReportOntoAFullDiskNamesTheFileItCouldNotWriteOnItsLastLine) {
    // A complete batch where there is room; then its figures (report.py, through gdnav report) and its review pages
    // (review.py) written onto a tiny file system: each ends with exit code 6 and one last line naming the file, no
    // traceback, and gdnav report starts no review.py after report.py was refused.
    const fs::path dir = temp_dir("full-disk-report");
    const fs::path batch = dir / "batch";
    ASSERT_EQ(run({kExe, "montecarlo", "--scenario", "2", "--runs", "2", "--jobs", "2", "--steps", "16000", "--layout",
                   "direct", "--seed", "1", "--no-report", "--out", batch.string()},
                  300.0)
                  .exit_code,
              0);
    TinyDisk disk("full-disk-report-out", 160 * 1024, 48 * 1024);
    SCOPED_TRACE(disk.mounted() ? "tmpfs" : "file size limit");
    const Result figures =
        run(disk.command({kExe, "report", batch.string(), "--out", (disk.dir() / "report").string()}), 240.0);
    EXPECT_EQ(figures.exit_code, 6) << figures.output;
    EXPECT_EQ(figures.output.find("Traceback"), std::string::npos) << figures.output;
    EXPECT_EQ(figures.output.find("review.py"), std::string::npos) << figures.output;
    const std::regex png(R"(^report\.py: \S+/report/\S+\.png: (No space left on device|File too large)$)");
    EXPECT_TRUE(std::regex_search(last_line(figures.output), png)) << figures.output;

    ASSERT_EQ(run({kExe, "report", batch.string(), "--no-figures"}, 240.0).exit_code, 0);  // tables.md, runs.csv
    const fs::path tables = batch / "report" / "tables.md", runs_csv = batch / "report" / "runs.csv";
    const std::string review_py = std::string(GDNAV_SOURCE_DIR) + "/tools/report/review.py";
    const Result pages = run(disk.command({"/usr/bin/python3", review_py, batch.string(), "--out",
                                           (disk.dir() / "review").string(), "--tables", tables.string(),
                                           "--runs-csv", runs_csv.string()}),
                             240.0);
    EXPECT_EQ(pages.exit_code, 6) << pages.output;
    EXPECT_EQ(pages.output.find("Traceback"), std::string::npos) << pages.output;
    const std::regex js(R"(^review\.py: \S+/review/\S+: (No space left on device|File too large)$)");
    EXPECT_TRUE(std::regex_search(last_line(pages.output), js)) << pages.output;
}
