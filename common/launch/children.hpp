#pragma once
// The launcher's child processes: start, reap, signal and wait for them.
#include <sys/types.h>

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace gdnav::runtime {

struct Child {
    std::string name;
    pid_t pid{0};
    bool running{true};
    int status{0};
};

// Starts `exe` with `args`, to end with the launcher; keep_fd: a descriptor it inherits (others are close-on-exec).
pid_t spawn(const std::filesystem::path& exe, const std::vector<std::string>& args, int keep_fd = -1);
// "exit code N", "killed by signal N".
std::string describe_status(int status);
// Collects every child that ended, calling on_exit once for each.
void reap(std::vector<Child>& children, const std::function<void(Child&)>& on_exit);
bool any_running(const std::vector<Child>& cs);
void signal_all(std::vector<Child>& cs, int sig);
// Waits up to `seconds` for all children; returns true when none is left.
bool wait_all(std::vector<Child>& cs, double seconds, const std::function<void(Child&)>& on_exit);

}  // namespace gdnav::runtime
