#pragma once
// gdnav report over several directories: which of them are parts (shards) of one batch, and the complete runs of
// such a set merged as one local batch would hold them (sorted by run index), with missing and duplicate indices.
#include <filesystem>
#include <string>
#include <vector>

#include "metrics/run_record.hpp"

namespace gdnav::launch::batch {

// The directories grouped into report blocks, each a list of directories of one batch:
//   * all directories of one batch (same scenario.yaml, i.e. scenario, overrides, seed, steps; same run range):
//     one block, whatever their shards;
//   * otherwise each directory is its own block (batches side by side), unless one of them is a shard directory
//     lacking runs of its batch: then config::ConfigError (one line: which two directories, what differs).
std::vector<std::vector<std::filesystem::path>> group_batch_dirs(const std::vector<std::filesystem::path>& dirs);

struct MergedRuns {
    std::vector<metrics::RunRecord> runs;      // complete runs, sorted by run index, each index once
    std::vector<std::uint64_t> missing;        // indices of the batch range without a complete run
    std::vector<std::uint64_t> duplicates;     // indices found complete in more than one directory (identical)
};
// Complete runs of the directories of one block. A run index complete in two directories with different
// metrics.yaml is a config::ConfigError (not one batch, or not reproducible); identical ones count once.
MergedRuns merge_complete_runs(const std::vector<std::filesystem::path>& dirs);

// "3, 6-8, 12"
std::string index_ranges(const std::vector<std::uint64_t>& sorted);

}  // namespace gdnav::launch::batch
