#include "launch/batch/batch_dir.hpp"

#include <gtest/gtest.h>

#include "config/config.hpp"
#include "temp_dir.hpp"

namespace gdnav::launch::batch {
namespace {

TEST(BatchDir, ParseShardAcceptsIOfN) {
    const Shard s = parse_shard("2/3");
    EXPECT_EQ(s.index, 2u);
    EXPECT_EQ(s.count, 3u);
    EXPECT_FALSE(s.whole());
    EXPECT_TRUE(parse_shard("1/1").whole());
}

TEST(BatchDir, ParseShardRejectsOutOfRangeWithOneLine) {
    for (const char* bad : {"0/3", "4/3", "3", "1/0", "a/b", "1/200000"}) {
        try {
            (void)parse_shard(bad);
            FAIL() << bad << " was accepted";
        } catch (const config::ConfigError& e) {
            EXPECT_EQ(std::string(e.what()), std::string("montecarlo: --shard must be I/N with 1 <= I <= N <= 100000 "
                                                         "(I is 1-based), got '") + bad + "'");
        }
    }
}

TEST(BatchDir, ShardsInterleaveAndCoverTheBatchOnce) {
    // Runs 10..16 (k = 0..6) in 3 shards: shard I holds k with k mod 3 == I - 1.
    EXPECT_EQ(shard_runs(10, 7, Shard{1, 3}), (std::vector<std::uint64_t>{10, 13, 16}));
    EXPECT_EQ(shard_runs(10, 7, Shard{2, 3}), (std::vector<std::uint64_t>{11, 14}));
    EXPECT_EQ(shard_runs(10, 7, Shard{3, 3}), (std::vector<std::uint64_t>{12, 15}));
    EXPECT_EQ(shard_runs(10, 7, Shard{}), (std::vector<std::uint64_t>{10, 11, 12, 13, 14, 15, 16}));
    EXPECT_TRUE(shard_runs(0, 2, Shard{3, 3}).empty());
}

TEST(BatchDir, RunDirNameHasFourDigitsAtLeast) {
    EXPECT_EQ(run_dir_name(7), "run_0007");
    EXPECT_EQ(run_dir_name(12345), "run_12345");
}

TEST(BatchDir, AtomicWriteReplacesTheFileAndLeavesNoTemporary) {
    test::TempDir t;
    const auto f = t.path() / "a.yaml";
    write_file_atomic(f, "first\n");
    write_file_atomic(f, "second: 2\n");
    EXPECT_EQ(read_text(f), "second: 2\n");
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(t.path())) ++files;
    EXPECT_EQ(files, 1u);
}

TEST(BatchDir, ReadBatchDirReadsBatchYamlAndShardRecords) {
    test::TempDir t;
    const auto dir = t.path();
    write_file_atomic(dir / "scenario.yaml", "run: {seed: 5}\n");
    write_file_atomic(dir / "batch.yaml", "scenario: 2\ngenerator: paper_scenario2\nseed: 5\nfirst: 3\nruns: 8\n"
                                          "layout: direct\nshards: 4\n");
    write_shard_record(dir, Shard{2, 4}, 3, 2);
    write_shard_record(dir, Shard{1, 4}, 3, 2);
    const BatchDirInfo info = read_batch_dir(dir);
    EXPECT_EQ(info.scenario_text, "run: {seed: 5}\n");
    EXPECT_EQ(info.scenario, "2");
    EXPECT_EQ(info.generator, "paper_scenario2");
    EXPECT_TRUE(info.has_range);
    EXPECT_EQ(info.seed, 5u);
    EXPECT_EQ(info.first, 3u);
    EXPECT_EQ(info.runs, 8u);
    EXPECT_EQ(info.shards, 4u);
    EXPECT_EQ(info.shard_records, (std::vector<std::string>{"1/4", "2/4"}));
}

TEST(BatchDir, ReadBatchDirWithoutBatchYamlHasNoRange) {
    test::TempDir t;
    const BatchDirInfo info = read_batch_dir(t.path());
    EXPECT_FALSE(info.has_range);
    EXPECT_TRUE(info.scenario_text.empty());
    EXPECT_TRUE(info.shard_records.empty());
}

}  // namespace
}  // namespace gdnav::launch::batch
