#include "dds/process/process_priority.hpp"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace gdnav::dds {

namespace {

int tid_of(int tid) { return tid != 0 ? tid : static_cast<int>(::syscall(SYS_gettid)); }

}  // namespace

int current_tid() { return tid_of(0); }

int thread_nice(int tid) {
    errno = 0;
    return ::getpriority(PRIO_PROCESS, static_cast<id_t>(tid_of(tid)));  // PRIO_PROCESS with a TID: that thread
}

std::string lower_cpu_priority(int nice, int keep_tid) {
    if (nice < 1 || nice > 19) return "nice value " + std::to_string(nice) + " outside 1..19";
    const auto set = [nice](int tid) -> std::string {
        if (thread_nice(tid) >= nice || ::setpriority(PRIO_PROCESS, static_cast<id_t>(tid), nice) == 0) return {};
        if (errno == ESRCH) return {};  // the thread ended since the listing
        return "setpriority(" + std::to_string(nice) + ") of thread " + std::to_string(tid) + ": " +
               std::strerror(errno);
    };
    // The calling thread first: the threads it creates from now on inherit its value.
    if (std::string p = set(tid_of(0)); !p.empty()) return p;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator("/proc/self/task", ec)) {
        const int tid = std::atoi(entry.path().filename().c_str());
        if (tid <= 0 || tid == keep_tid) continue;
        if (std::string p = set(tid); !p.empty()) return p;
    }
    if (ec) return "cannot list /proc/self/task: " + ec.message();
    return {};
}

}  // namespace gdnav::dds
