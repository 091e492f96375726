#pragma once
// The launcher's child processes: start, reap, signal and wait for them.
#include <sys/types.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace gdnav::launch {

struct Child {
    std::string name;
    pid_t pid{0};
    bool running{true};
    int status{0};
};

// How a child starts beyond its program and arguments.
struct SpawnOptions {
    std::filesystem::path log;        // "" = the launcher's stdout and stderr; else both go to this file
    bool log_truncate{false};         // the log file is emptied first (else appended to)
    std::filesystem::path cwd;        // "" = the launcher's working directory
    const std::vector<std::string>* env{nullptr};  // "K=V" entries: the child's whole environment (nullptr: ours)
    int keep_fd{-1};                  // a descriptor it inherits (others are close-on-exec)
};

// Starts `exe` with the argument vector `argv` (argv[0] included), to end with the launcher (PR_SET_PDEATHSIG).
// Everything is prepared before fork: the child makes only async-signal-safe calls.
pid_t spawn_argv(const std::filesystem::path& exe, const std::vector<std::string>& argv, const SpawnOptions& o);
// spawn_argv with argv = {exe, args...}.
pid_t spawn(const std::filesystem::path& exe, const std::vector<std::string>& args, const SpawnOptions& o);
pid_t spawn(const std::filesystem::path& exe, const std::vector<std::string>& args, int keep_fd = -1);
// "exit code N", "killed by signal N".
std::string describe_status(int status);
// Collects every child that ended, calling on_exit once for each.
void reap(std::vector<Child>& children, const std::function<void(Child&)>& on_exit);
bool any_running(const std::vector<Child>& cs);
void signal_all(std::vector<Child>& cs, int sig);
// Waits up to `seconds` for all children; returns true when none is left.
bool wait_all(std::vector<Child>& cs, double seconds, const std::function<void(Child&)>& on_exit);

}  // namespace gdnav::launch
