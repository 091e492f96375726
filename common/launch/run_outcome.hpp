#pragma once
// The closing line of `gdnav run`: how the run ended, from the clock's <out>/clock_summary.yaml and the exit status
// of each process the launcher started. A failed run ends with one line naming the first cause (the clock's reason,
// or the first process that failed) and the exit code; a run completed without some member names each one and why.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace gdnav::launch {

struct DeadMember {
    std::string name;
    std::uint64_t step{0};
    std::string reason;  // "" in summaries written before the clock recorded reasons
};

// What the launcher needs of clock_summary.yaml (docs/protocol.md §5).
struct ClockSummary {
    bool found{false};         // the file exists and parses
    std::string abort_reason;  // "" when the run completed
    std::vector<DeadMember> dead;
};

// A missing or unreadable file gives found = false (the clock died before writing it).
ClockSummary read_clock_summary(const std::filesystem::path& file);

// A process of the run that did not end with exit code 0: "name (how it ended)", in the order they ended.
// `failures` excludes the members that only followed the clock's ABORT (exit code 3).
std::string failed_run_line(int code, const ClockSummary& summary, const std::vector<std::string>& failures);

// "run completed; results in DIR", or "run completed without: A (declared dead at step n: why), B (killed by signal
// 6); results in DIR".
std::string completed_run_line(const ClockSummary& summary, const std::vector<std::string>& failures,
                               const std::string& out_dir);

}  // namespace gdnav::launch
