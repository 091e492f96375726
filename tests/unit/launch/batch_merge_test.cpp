#include "launch/batch/batch_merge.hpp"

#include <gtest/gtest.h>

#include "config/config.hpp"
#include "launch/batch/batch_dir.hpp"
#include "temp_dir.hpp"
#include "metrics/run_record.hpp"

namespace gdnav::launch::batch {
namespace {

namespace fs = std::filesystem;

// A batch directory as gdnav montecarlo --shard leaves it: scenario.yaml, batch.yaml (seed, runs 0..runs-1) and
// complete runs with the given indices (each run's hor final error = its index, so merged runs can be told apart).
void make_batch_dir(const fs::path& dir, std::uint64_t seed, std::uint64_t runs, std::uint64_t shards,
                    const std::vector<std::uint64_t>& complete) {
    fs::create_directories(dir / "runs");
    write_file_atomic(dir / "scenario.yaml", "run: {seed: " + std::to_string(seed) + ", steps: 10}\n");
    write_file_atomic(dir / "batch.yaml", "scenario: 1\ngenerator: paper_scenario1\nseed: " + std::to_string(seed) +
                                              "\nfirst: 0\nruns: " + std::to_string(runs) + "\nlayout: direct\n" +
                                              (shards ? "shards: " + std::to_string(shards) + "\n" : "jobs: 2\n"));
    for (const std::uint64_t i : complete) {
        metrics::RunRecord r;
        r.complete = true;
        r.seed = seed;
        r.run_index = i;
        r.steps = 10;
        r.hor_pct = static_cast<double>(i);
        fs::create_directories(dir / "runs" / run_dir_name(i));
        metrics::write_run_record(dir / "runs" / run_dir_name(i) / "metrics.yaml", r);
    }
}

TEST(BatchMerge, IndexRanges) {
    EXPECT_EQ(index_ranges({3, 6, 7, 8, 12}), "3, 6-8, 12");
    EXPECT_EQ(index_ranges({0, 1}), "0-1");
    EXPECT_EQ(index_ranges({}), "");
}

TEST(BatchMerge, ShardsOfOneBatchAreOneBlockWithTheirRunsMerged) {
    test::TempDir t;
    make_batch_dir(t.path() / "a", 1, 5, 2, {0, 2});
    make_batch_dir(t.path() / "b", 1, 5, 2, {1, 3});
    const auto groups = group_batch_dirs({t.path() / "a", t.path() / "b"});
    ASSERT_EQ(groups.size(), 1u);
    EXPECT_EQ(groups.front().size(), 2u);
    const MergedRuns m = merge_complete_runs(groups.front());
    ASSERT_EQ(m.runs.size(), 4u);
    for (std::size_t i = 0; i < m.runs.size(); ++i) {
        EXPECT_EQ(m.runs[i].run_index, i);
        EXPECT_EQ(m.runs[i].hor_pct, static_cast<double>(i));
    }
    EXPECT_EQ(m.missing, (std::vector<std::uint64_t>{4}));
    EXPECT_TRUE(m.duplicates.empty());
}

TEST(BatchMerge, IdenticalRunInTwoDirectoriesCountsOnce) {
    test::TempDir t;
    make_batch_dir(t.path() / "a", 1, 2, 2, {0, 1});
    make_batch_dir(t.path() / "b", 1, 2, 2, {1});
    const MergedRuns m = merge_complete_runs({t.path() / "a", t.path() / "b"});
    EXPECT_EQ(m.runs.size(), 2u);
    EXPECT_EQ(m.duplicates, (std::vector<std::uint64_t>{1}));
    EXPECT_TRUE(m.missing.empty());
}

TEST(BatchMerge, DifferentRunOfOneIndexIsAnError) {
    test::TempDir t;
    make_batch_dir(t.path() / "a", 1, 2, 2, {0});
    make_batch_dir(t.path() / "b", 1, 2, 2, {0});
    metrics::RunRecord other = metrics::read_run_record(t.path() / "b/runs/run_0000/metrics.yaml");
    other.hor_pct = 99.0;
    metrics::write_run_record(t.path() / "b/runs/run_0000/metrics.yaml", other);
    EXPECT_THROW((void)merge_complete_runs({t.path() / "a", t.path() / "b"}), config::ConfigError);
}

TEST(BatchMerge, WholeBatchesOfDifferentSeedsStandSideBySide) {
    test::TempDir t;
    make_batch_dir(t.path() / "a", 1, 2, 0, {0, 1});
    make_batch_dir(t.path() / "b", 2, 2, 0, {0, 1});
    const auto groups = group_batch_dirs({t.path() / "a", t.path() / "b"});
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0], (std::vector<fs::path>{t.path() / "a"}));
    EXPECT_EQ(groups[1], (std::vector<fs::path>{t.path() / "b"}));
}

TEST(BatchMerge, IncompleteShardOfAnotherBatchNamesBothDirectoriesAndTheSeeds) {
    test::TempDir t;
    make_batch_dir(t.path() / "a", 1, 4, 2, {0, 2});
    make_batch_dir(t.path() / "b", 2, 4, 2, {1, 3});
    try {
        (void)group_batch_dirs({t.path() / "a", t.path() / "b"});
        FAIL() << "no error";
    } catch (const config::ConfigError& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find((t.path() / "a").string() + " (a shard) and " + (t.path() / "b").string()), std::string::npos)
            << m;
        EXPECT_NE(m.find("(seed 1 vs 2)"), std::string::npos) << m;
    }
}

TEST(BatchMerge, DirectoryWithoutRunsIsAnError) {
    test::TempDir t;
    EXPECT_THROW((void)group_batch_dirs({t.path()}), config::ConfigError);
}

}  // namespace
}  // namespace gdnav::launch::batch
