#pragma once
// Helpers for integration tests that start real gdnav processes.
#include <sys/types.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "run_folders.hpp"
#include "test_paths.hpp"

namespace gdnav::testing {

struct Result {
    int exit_code{-1};   // exit status, or 128 + signal
    std::string output;  // stdout + stderr
    double wall_s{0.0};
};

// Runs argv (no shell) with a wall-clock limit; kills the process group on overrun.
Result run(const std::vector<std::string>& argv, double timeout_s = 120.0);

// Starts argv in the background with output to `log`; returns its pid.
pid_t start(const std::vector<std::string>& argv, const std::filesystem::path& log);
// Waits for pid; returns exit code (128 + signal) or -1 on timeout (timeout 0: one check, no wait).
int wait_for(pid_t pid, double timeout_s);

// A run and an external member started together (gdnav run ... --external NAME, and the member), both waited for;
// the run gets `timeout_s`, the member 30 s more; overrunning processes are killed. Logs: <log_base>.run.log and
// <log_base>.member.log.
struct PairResult {
    int run_code{-1}, member_code{-1};
    std::string run_log, member_log;
};
PairResult run_pair(const std::vector<std::string>& run_argv, const std::vector<std::string>& member_argv,
                    const std::filesystem::path& log_base, double timeout_s);

bool alive(pid_t pid);
// Waits until the file `log` contains `text`; false when `pid` is no longer alive or after timeout_s.
bool wait_for_log(pid_t pid, const std::filesystem::path& log, const std::string& text, double timeout_s);
std::string read_file(const std::filesystem::path& p);
// How many times `what` occurs in `text` (overlapping occurrences counted), e.g. a log line that must appear once.
std::size_t count_of(const std::string& text, const std::string& what);
std::map<std::string, pid_t> read_processes(const std::filesystem::path& out_dir);
// topic -> digest of <out>/record/digest.yaml (empty when missing).
std::map<std::string, std::string> read_digests(const std::filesystem::path& out_dir);
// Checks (EXPECT) that every Markdown table in `md` has the same number of cells in each of its lines (escaped \|
// not counted) and returns how many tables there are.
int expect_consistent_markdown_tables(const std::string& md);
// A TCP port on 127.0.0.1 that was free a moment ago (bound to 0, read back, closed); -1 if none.
int free_port();
// Path of gdnav-testchain and of the chain scenario.
std::string testchain_exe();
std::string chain_scenario();

}  // namespace gdnav::testing
