// gdnav montecarlo --shard I/N and --mpi, gdnav report over shard directories: a 5-run batch of
// scenario #2 with the navigation filters (16000 steps, so the errors are real) run locally, as 3 shards in 3
// directories and as 3 MPI ranks gives the same per-run metrics and the same tables, aggregate.yaml and runs.csv; a
// missing shard, a duplicate directory and a shard of another batch are reported or refused; a bad --shard is one
// line and exit 2. The MPI batch also runs with rank 0 in another folder than the other ranks (no shared file system).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <regex>
#include <sstream>

#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {


std::vector<std::string> batch_cmd(const fs::path& out, const std::string& seed = "5") {
    return {kExe, "montecarlo", "--scenario", "2", "--runs", "5", "--steps", "16000", "--seed", seed, "--jobs", "1",
            "--no-figures", "--out", out.string()};
}

std::vector<std::string> with(std::vector<std::string> cmd, const std::vector<std::string>& more) {
    cmd.insert(cmd.end(), more.begin(), more.end());
    return cmd;
}

// tables.md without the lines that name the directories ("- FOLDER (#2): 5 complete runs in DIR, DIR") and with the
// label of its block (FOLDER (#2), FOLDER the name of the block's first folder) replaced by "#2".
std::string tables_without_dirs(const fs::path& report) {
    std::istringstream in(read_file(report / "tables.md"));
    static const std::regex label(R"([^ |]+ \(#2\))");
    std::string line, out;
    while (std::getline(in, line))
        if (line.rfind("- ", 0) != 0) out += std::regex_replace(line, label, "#2") + "\n";
    return out;
}

void expect_same_report(const fs::path& a, const fs::path& b) {
    ASSERT_TRUE(fs::exists(a / "aggregate.yaml"));
    ASSERT_TRUE(fs::exists(b / "aggregate.yaml"));
    EXPECT_EQ(read_file(a / "aggregate.yaml"), read_file(b / "aggregate.yaml"));
    EXPECT_EQ(read_file(a / "runs.csv"), read_file(b / "runs.csv"));
    EXPECT_EQ(tables_without_dirs(a), tables_without_dirs(b));
    EXPECT_NE(read_file(a / "aggregate.yaml").find("runs: 5\nrun_indices: [0, 1, 2, 3, 4]"), std::string::npos);
}

std::string metrics_of(const fs::path& batch, int run) {
    char b[32];
    std::snprintf(b, sizeof(b), "run_%04d", run);
    return read_file(batch / "runs" / b / "metrics.yaml");
}

fs::path local_batch() {
    const fs::path dir = temp_dir("local");
    const Result r = run(batch_cmd(dir), 180.0);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return dir;
}

}  // namespace

TEST(MonteCarloShards, ThreeShardDirectoriesGiveTheTablesOfTheLocalBatch) {
    const fs::path local = local_batch();
    std::vector<fs::path> shards;
    for (int i = 1; i <= 3; ++i) {
        shards.push_back(temp_dir("shard" + std::to_string(i)));
        const Result r = run(with(batch_cmd(shards.back()), {"--shard", std::to_string(i) + "/3"}), 180.0);
        ASSERT_EQ(r.exit_code, 0) << r.output;
        EXPECT_EQ(r.output.find("report: tables written"), std::string::npos) << "a shard makes no report";
        EXPECT_TRUE(fs::exists(shards.back() / "shards" / ("shard_" + std::to_string(i) + "_of_3.yaml")));
    }
    // Interleaved slices: shard I holds the runs k with k mod 3 = I - 1, each equal to the local batch's run.
    for (int k = 0; k < 5; ++k)
        for (int i = 0; i < 3; ++i) {
            const std::string m = metrics_of(shards[static_cast<std::size_t>(i)], k);
            if (k % 3 == i)
                EXPECT_EQ(m, metrics_of(local, k)) << "run " << k;
            else
                EXPECT_TRUE(m.empty()) << "run " << k << " in shard " << i + 1;
        }
    const fs::path rep = temp_dir("shards_report");
    const Result r = run({kExe, "report", shards[0].string(), shards[1].string(), shards[2].string(), "--out",
                          rep.string(), "--no-figures"},
                         60.0);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(r.output.find("missing"), std::string::npos) << r.output;
    expect_same_report(rep, local / "report");

    // A shard missing: reported (tables of the runs there are), the missing indices named.
    const Result two = run({kExe, "report", shards[0].string(), shards[2].string(), "--out",
                            (rep / "two").string(), "--no-figures"},
                           60.0);
    EXPECT_EQ(two.exit_code, 0) << two.output;
    EXPECT_NE(two.output.find("2 run(s) of the batch missing or incomplete: 1, 4"), std::string::npos) << two.output;
    EXPECT_NE(read_file(rep / "two" / "tables.md").find("(missing runs: 1, 4)"), std::string::npos);
    // A shard given twice: its runs counted once, the duplicates named.
    const Result dup = run({kExe, "report", shards[0].string(), shards[1].string(), shards[2].string(),
                            shards[2].string(), "--out", (rep / "dup").string(), "--no-figures"},
                           60.0);
    EXPECT_EQ(dup.exit_code, 0) << dup.output;
    EXPECT_NE(dup.output.find("run(s) 2 found in more than one directory"), std::string::npos) << dup.output;
    expect_same_report(rep / "dup", local / "report");
    // A shard of another batch (another seed) is refused.
    const fs::path other = temp_dir("other_seed");
    const Result o = run(with(batch_cmd(other, "6"), {"--shard", "3/3"}), 180.0);
    ASSERT_EQ(o.exit_code, 0) << o.output;
    const Result bad = run({kExe, "report", shards[0].string(), shards[1].string(), other.string(), "--out",
                            (rep / "bad").string(), "--no-figures"},
                           60.0);
    EXPECT_EQ(bad.exit_code, 2) << bad.output;
    EXPECT_NE(bad.output.find("are not of the same batch (seed 5 vs 6)"), std::string::npos) << bad.output;
}

TEST(MonteCarloShards, BadShardIsAOneLineError) {
    const fs::path dir = temp_dir("bad_shard");
    for (const char* s : {"0/3", "4/3", "3", "a/b", "1/0"}) {
        const Result r = run(with(batch_cmd(dir), {"--shard", s}), 60.0);
        EXPECT_EQ(r.exit_code, 2) << s << "\n" << r.output;
        EXPECT_NE(r.output.find("--shard must be I/N with 1 <= I <= N"), std::string::npos) << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
        EXPECT_FALSE(fs::exists(dir / "runs")) << "nothing may run";
    }
}

TEST(MonteCarloShards, MpiBatchGivesTheTablesOfTheLocalBatch) {
#ifndef GDNAV_MPIEXEC
    GTEST_SKIP() << "gdnav built without MPI";
#else
    const fs::path local = local_batch();
    const fs::path dir = temp_dir("mpi");
    std::vector<std::string> cmd{GDNAV_MPIEXEC, "--oversubscribe", "-np", "3"};
    if (geteuid() == 0) cmd.push_back("--allow-run-as-root");
    cmd = with(cmd, with(batch_cmd(dir), {"--mpi"}));
    const Result r = run(cmd, 240.0);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("3 ranks done"), std::string::npos) << r.output;
    for (int i = 1; i <= 3; ++i) EXPECT_TRUE(fs::exists(dir / "shards" / ("shard_" + std::to_string(i) + "_of_3.yaml")));
    for (int k = 0; k < 5; ++k) EXPECT_EQ(metrics_of(dir, k), metrics_of(local, k)) << "run " << k;
    expect_same_report(dir / "report", local / "report");

    // No shared file system: rank 0 and ranks 1-2 in different working directories (relative --out), so rank 0
    // sees only its own runs' files and writes the metrics the other ranks send.
    const fs::path split = temp_dir("mpi_split");
    fs::create_directories(split / "rank0");
    fs::create_directories(split / "others");
    std::vector<std::string> mpmd{GDNAV_MPIEXEC, "--oversubscribe"};
    if (geteuid() == 0) mpmd.push_back("--allow-run-as-root");
    std::vector<std::string> args = batch_cmd("m");
    args.push_back("--mpi");
    mpmd = with(mpmd, {"-np", "1", "--wdir", (split / "rank0").string()});
    mpmd = with(mpmd, args);
    mpmd = with(mpmd, {":", "-np", "2", "--wdir", (split / "others").string()});
    mpmd = with(mpmd, args);
    const Result s = run(mpmd, 240.0);
    ASSERT_EQ(s.exit_code, 0) << s.output;
    EXPECT_NE(s.output.find("wrote 3 runs' metrics.yaml sent by other ranks"), std::string::npos) << s.output;
    expect_same_report(split / "rank0" / "m" / "report", local / "report");
#endif
}
