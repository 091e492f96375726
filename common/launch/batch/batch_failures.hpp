#pragma once
// Failed runs of a Monte Carlo batch (docs/montecarlo.md, "Failed runs"):
//   DIR/runs/run_NNNN/failure.yaml  written when a run fails: run index, exit code, cause (the last line of the
//                                   run's log.txt), the last lines of log.txt and of each member log (logs/*.log);
//   DIR/failures.yaml               every failure.yaml of the folder, by run index (absent when no run failed).
// A failed run's metrics.yaml, if it wrote one, becomes metrics.failed.yaml: the run counts as missing, so running
// the same command again reruns it (and its folder, failure.yaml included, is made anew).
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace gdnav::launch::batch {

struct RunFailure {
    std::uint64_t run{0};
    int exit_code{0};
    std::string cause;                   // the last non-empty line of log.txt
    std::vector<std::string> log_tail;   // its last lines
    std::vector<std::pair<std::string, std::vector<std::string>>> member_tails;  // logs/NAME.log: last lines
};

inline constexpr std::size_t kFailureTailLines = 8;

// The last `n` non-empty lines of a text file (fewer when it is shorter; none when it is missing).
std::vector<std::string> last_lines(const std::filesystem::path& file, std::size_t n);

// Records the failure of the run in `run_dir` (failure.yaml; metrics.yaml moved aside) and returns it.
RunFailure record_run_failure(const std::filesystem::path& run_dir, std::uint64_t run, int exit_code);

// The failure.yaml of every run folder of a batch directory, by run index (unreadable ones are skipped).
std::vector<RunFailure> read_run_failures(const std::filesystem::path& batch_dir);

// Writes DIR/failures.yaml from the run folders (removes it when no run failed).
void write_failures_summary(const std::filesystem::path& batch_dir);

// The failed runs as Markdown: one heading per run with its cause and its last log lines.
std::string failures_markdown(const std::vector<RunFailure>& failures, const std::string& where);

}  // namespace gdnav::launch::batch
