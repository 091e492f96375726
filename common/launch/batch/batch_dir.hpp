#pragma once
// A Monte Carlo batch directory (gdnav montecarlo --out DIR) and its shards:
//   DIR/scenario.yaml            the scenario with every override applied: the batch's identity (config, seed, steps)
//   DIR/batch.yaml               scenario name, generator, seed, first run, run count, layout (+ `shards: N`)
//   DIR/shards/shard_I_of_N.yaml one per shard that ran into DIR (gdnav montecarlo --shard I/N or --mpi)
//   DIR/runs/run_NNNN/           one folder per run index
// Shard I of N (1-based, 1 <= I <= N) holds the runs first + k, k = 0 .. runs-1, with k mod N == I - 1 (interleaved
// slices). A run's seeds depend only on (master seed, run index), so a run is the same bits whichever shard runs it.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gdnav::launch::batch {

struct Shard {
    std::uint64_t index{1};  // I, 1-based
    std::uint64_t count{1};  // N; 1/1 is the whole batch
    [[nodiscard]] bool whole() const { return count == 1; }
};

// "I/N" -> Shard; throws config::ConfigError (one line) unless 1 <= I <= N <= 100000.
Shard parse_shard(const std::string& text);
// The run indices of shard `s` of the batch first .. first + runs - 1.
std::vector<std::uint64_t> shard_runs(std::uint64_t first, std::uint64_t runs, const Shard& s);

// run_0007
std::string run_dir_name(std::uint64_t index);
// Writes `text` to `file` through a temporary file and a rename, so concurrent writers of the same text (shards
// sharing one DIR) and readers never see half a file.
void write_file_atomic(const std::filesystem::path& file, const std::string& text);
std::string read_text(const std::filesystem::path& file);

// What identifies a batch directory (read from scenario.yaml and batch.yaml; empty / 0 where absent).
struct BatchDirInfo {
    std::filesystem::path dir;
    std::string scenario_text;  // scenario.yaml
    std::string scenario;       // batch.yaml `scenario` (1, 2, a name or a file)
    std::string generator;
    bool has_range{false};  // batch.yaml gives seed, first and runs
    std::uint64_t seed{0};
    std::uint64_t first{0};
    std::uint64_t runs{0};
    std::uint64_t shards{0};                  // N when written by shards, else 0
    std::vector<std::string> shard_records;  // "I/N" of each shard that ran into this directory
};
BatchDirInfo read_batch_dir(const std::filesystem::path& dir);

// Records that shard `s` ran into `dir` (DIR/shards/shard_I_of_N.yaml).
void write_shard_record(const std::filesystem::path& dir, const Shard& s, unsigned jobs, std::size_t runs);

}  // namespace gdnav::launch::batch
