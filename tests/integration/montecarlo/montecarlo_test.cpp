// gdnav montecarlo / report / scenario end to end (real gdnav processes):
//   * a 3-run batch of each paper scenario (truth templates, shortened with --steps) produces well-formed tables,
//     figures and per-run files;
//   * a batch run re-executed alone with `gdnav run` in the distributed layout has a bit-identical metrics.yaml
//     (real navigation filters, so the errors are not trivially zero);
//   * a batch interrupted with SIGTERM and started again completes only the missing runs.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <thread>

#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

// 16000 steps from t0 = -50 s: t_end = 109.99 s, past t_GNSS = 100 s, so distances and percentages exist.
const std::string kSteps = "16000";

bool complete(const fs::path& metrics) {
    return read_file(metrics).find("\ncomplete: true\n") != std::string::npos;
}

// Every table of tables.md: a header line, a separator line and rows, all with the same number of cells.
void expect_well_formed_tables(const std::string& md, const std::string& label) {
    for (const char* title : {"Aggregated body attitude NSE", "Aggregated final vertical position",
                              "Aggregated final ground speed NSE", "Aggregated final horizontal position NSE"})
        EXPECT_NE(md.find(title), std::string::npos) << title << "\n" << md;
    EXPECT_NE(md.find(" (" + label + ") | mean |"), std::string::npos) << md;  // "| FOLDER (#2) | mean |"
    EXPECT_EQ(md.find("n/a"), std::string::npos) << md;
    EXPECT_GE(expect_consistent_markdown_tables(md), 6);
}

void expect_png(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    char magic[8] = {};
    f.read(magic, 8);
    EXPECT_EQ(std::string(magic + 1, 3), "PNG") << p;
    EXPECT_GT(fs::file_size(p), 20000u) << p;  // a real plot, not an empty canvas
}

}  // namespace

TEST(MonteCarlo, ThreeRunBatchOfEachScenarioGivesTablesFiguresAndFiles) {
    for (const auto& [scenario, label] : {std::pair{"paper1_truth", "#1"}, std::pair{"paper2_truth", "#2"}}) {
        SCOPED_TRACE(scenario);
        const fs::path dir = temp_dir(std::string("batch_") + scenario);
        const Result r = run({kExe, "montecarlo", "--scenario", scenario, "--runs", "3", "--jobs", "2", "--layout",
                              "direct", "--steps", kSteps, "--seed", "4", "--out", dir.string()},
                             120.0);
        ASSERT_EQ(r.exit_code, 0) << r.output;
        EXPECT_NE(r.output.find("3/3 runs done, 0 failed"), std::string::npos) << r.output;
        EXPECT_TRUE(fs::exists(dir / "scenario.yaml"));
        EXPECT_TRUE(fs::exists(dir / "batch.yaml"));
        for (int i = 0; i < 3; ++i) {
            EXPECT_TRUE(complete(fs::path(run_dir(dir, i)) / "metrics.yaml")) << i;
            EXPECT_GT(fs::file_size(fs::path(run_dir(dir, i)) / "run.h5"), 10000u);
            EXPECT_NE(read_file(fs::path(run_dir(dir, i)) / "run.yaml").find("run_index: " + std::to_string(i)),
                      std::string::npos);
        }
        const fs::path rep = dir / "report";
        expect_well_formed_tables(read_file(rep / "tables.md"), label);
        EXPECT_NE(read_file(rep / "aggregate.yaml").find("runs: 3\nrun_indices: [0, 1, 2]"), std::string::npos);
        const std::string csv = read_file(rep / "runs.csv");
        EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 4);
        for (const char* png : {"attitude_nse.png", "altitude_nse.png", "ground_speed_nse.png", "horizontal_nse.png",
                                "air_data_nse.png", "attitude_scatter.png", "horizontal_final.png"})
            expect_png(rep / png);
        // gdnav report regenerates the same tables.
        const std::string before = read_file(rep / "tables.md");
        fs::remove(rep / "tables.md");
        const Result rr = run({kExe, "report", dir.string(), "--no-figures"}, 60.0);
        EXPECT_EQ(rr.exit_code, 0) << rr.output;
        EXPECT_EQ(read_file(rep / "tables.md"), before);
    }
}

TEST(MonteCarlo, BatchRunEqualsASingleDistributedRunBitForBit) {
    const fs::path dir = temp_dir("identity");
    const Result b = run({kExe, "montecarlo", "--scenario", "2", "--runs", "2", "--jobs", "2", "--steps", kSteps,
                          "--seed", "5", "--no-figures", "--out", dir.string()},
                         120.0);
    ASSERT_EQ(b.exit_code, 0) << b.output;
    const fs::path single = temp_dir("identity_single");
    const Result s = run({kExe, "run", "--scenario", "paper2", "--seed", "5", "--run", "1", "--steps", kSteps,
                          "--layout", "distributed", "--out", single.string()},
                         180.0);
    ASSERT_EQ(s.exit_code, 0) << s.output;
    EXPECT_EQ(s.output.find("run completed without"), std::string::npos) << s.output;  // every process ended well
    const std::string batch_metrics = read_file(fs::path(run_dir(dir, 1)) / "metrics.yaml");
    EXPECT_TRUE(complete(fs::path(run_dir(dir, 1)) / "metrics.yaml"));
    EXPECT_EQ(batch_metrics, read_file(single / "metrics.yaml"));
    // The navigation errors are real (not the zeros of a truth loop), so the equality means something.
    EXPECT_EQ(batch_metrics.find("hor_m: {mean: 0,"), std::string::npos) << batch_metrics;
    // And run 0 differs from run 1.
    EXPECT_NE(read_file(fs::path(run_dir(dir, 0)) / "metrics.yaml"), batch_metrics);
}

TEST(MonteCarlo, InterruptedBatchCompletesOnlyTheMissingRuns) {
    const fs::path dir = temp_dir("resume");
    const std::vector<std::string> cmd{kExe,         "montecarlo", "--scenario", "paper1_truth", "--runs", "4",
                                       "--jobs",     "2",          "--steps",    "150000",       "--seed", "6",
                                       "--no-figures", "--out",    dir.string()};
    const fs::path log = dir.parent_path() / (dir.filename().string() + ".log");
    const pid_t pid = start(cmd, log);
    // Wait for the first complete run, then interrupt the runner while the others are in flight.
    std::set<int> done;
    for (int i = 0; i < 6000 && done.empty() && alive(pid); ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        for (int k = 0; k < 4; ++k)
            if (complete(fs::path(run_dir(dir, k)) / "metrics.yaml")) done.insert(k);
    }
    ASSERT_FALSE(done.empty()) << read_file(log);
    ASSERT_TRUE(alive(pid)) << "the batch ended before it could be interrupted:\n" << read_file(log);
    kill(pid, SIGTERM);
    EXPECT_EQ(wait_for(pid, 60.0), 130) << read_file(log);
    EXPECT_NE(read_file(log).find("interrupted"), std::string::npos) << read_file(log);
    std::set<int> complete_after;
    std::map<int, fs::file_time_type> stamp;
    for (int k = 0; k < 4; ++k) {
        const fs::path m = fs::path(run_dir(dir, k)) / "metrics.yaml";
        if (complete(m)) {
            complete_after.insert(k);
            stamp[k] = fs::last_write_time(m);
        }
    }
    ASSERT_LT(complete_after.size(), 4u) << read_file(log);
    // The interrupted runs left readable HDF5 files marked incomplete (checked with h5py, no gdnav code).
    for (int k = 0; k < 4; ++k) {
        if (complete_after.count(k) || !fs::exists(fs::path(run_dir(dir, k)) / "run.h5")) continue;
        const Result py = run({"/usr/bin/python3", "-c",
                               "import h5py,sys; f=h5py.File(sys.argv[1],'r'); "
                               "print('complete', int(f.attrs['complete']), 'rows', f['error'].shape[0])",
                               (fs::path(run_dir(dir, k)) / "run.h5").string()},
                              60.0);
        EXPECT_EQ(py.exit_code, 0) << py.output;
        EXPECT_NE(py.output.find("complete 0 rows"), std::string::npos) << py.output;
    }

    const Result again = run(cmd, 180.0);
    ASSERT_EQ(again.exit_code, 0) << again.output;
    EXPECT_NE(again.output.find(std::to_string(complete_after.size()) + " already complete"), std::string::npos)
        << again.output;
    EXPECT_NE(again.output.find("(" + std::to_string(4 - complete_after.size()) + " new, " +
                                std::to_string(complete_after.size()) + " skipped)"),
              std::string::npos)
        << again.output;
    for (int k = 0; k < 4; ++k) {
        const fs::path m = fs::path(run_dir(dir, k)) / "metrics.yaml";
        EXPECT_TRUE(complete(m)) << k;
        if (complete_after.count(k)) {
            EXPECT_EQ(fs::last_write_time(m), stamp[k]) << "run " << k << " was re-run";
        }
    }
}

TEST(MonteCarlo, ScenarioCommandPrintsDrawsAndWritesARunnableConfig) {
    const fs::path dir = temp_dir("scenario");
    const Result r = run({kExe, "scenario", "--scenario", "1", "--seed", "1", "--run", "7", "--out",
                          (dir / "r7.yaml").string()},
                         60.0);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const char* s : {"paper scenario #1, seed 1, run 7", "mission", "wind", "atmosphere offsets", "Earth truth"})
        EXPECT_NE(r.output.find(s), std::string::npos) << s << "\n" << r.output;
    const Result v = run({kExe, "validate", "--scenario", (dir / "r7.yaml").string()}, 60.0);
    EXPECT_EQ(v.exit_code, 0) << v.output;
    const Result bad = run({kExe, "montecarlo", "--scenario", "2", "--runs", "1", "--out", (dir / "b").string(),
                            "--set", "generator.t_gnss=3"},
                           60.0);
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
    EXPECT_NE(bad.output.find("t_gnss"), std::string::npos) << bad.output;
}
