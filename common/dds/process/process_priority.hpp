#pragma once
// CPU priority of a process that hosts only observers (Component::observer, docs/protocol.md §6.4): nobody waits for
// an observer, so its process runs at a higher nice value and takes the CPU time the run's own members leave idle
// instead of competing with them for it (docs/viewing.md, "Cost"). Linux nice values are per thread: every thread
// of the process is changed, and threads created later inherit the creating thread's value.
#include <string>

#include "dds/compat.hpp"

namespace gdnav::dds {

// Sets every thread of this process but `keep_tid` (0: none) to `nice` (1..19; only ever raised: a thread already
// nicer keeps its value). The kept thread is the host's heartbeat pulse: a starved observer falls behind and skips
// steps, but stays alive for the clock. Returns an empty string, or what failed (the process then runs on at its old
// priority).
std::string lower_cpu_priority(int nice, int keep_tid = 0);

// The nice value of thread `tid` of this process (0: the calling thread); for tests and logs.
int thread_nice(int tid = 0);

// The calling thread's id (gettid).
int current_tid();

}  // namespace gdnav::dds
