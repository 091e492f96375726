// runtime/process_priority: a process of observers lowers the CPU priority of every thread it has, and the threads
// it starts afterwards inherit it. Each case runs in a forked child so that the test process keeps its priority.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <string>
#include <thread>

#include "dds/process/process_priority.hpp"

using gdnav::dds::lower_cpu_priority;
using gdnav::dds::thread_nice;

namespace {

// Runs `body` in a forked child; its return value is the child's exit code (0 = pass).
int in_child(int (*body)()) {
    const pid_t pid = ::fork();
    if (pid == 0) ::_exit(body());
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 100;
}

int min_nice_of_all_threads() {
    int lowest = 100;
    for (const auto& e : std::filesystem::directory_iterator("/proc/self/task"))
        lowest = std::min(lowest, thread_nice(std::atoi(e.path().filename().c_str())));
    return lowest;
}

}  // namespace

TEST(ProcessPriority, EveryThreadBeforeAndAfterGetsTheNiceValue) {
    if (thread_nice() >= 12) GTEST_SKIP() << "the test process already runs at nice " << thread_nice();
    EXPECT_EQ(in_child([]() -> int {
                  std::atomic<bool> stop{false};
                  std::atomic<int> before_nice{-1};
                  std::thread before([&] {  // a thread started before the call (like a DDS thread)
                      while (!stop) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                      before_nice = thread_nice();
                  });
                  if (!lower_cpu_priority(12).empty()) return 2;
                  if (thread_nice() != 12) return 3;
                  if (min_nice_of_all_threads() != 12) return 4;
                  int after_nice = -1;
                  std::thread after([&] { after_nice = thread_nice(); });  // started later: inherits
                  after.join();
                  stop = true;
                  before.join();
                  if (before_nice != 12) return 5;
                  if (after_nice != 12) return 6;
                  return 0;
              }),
              0);
}

TEST(ProcessPriority, TheKeptThreadKeepsItsValue) {
    if (thread_nice() >= 12) GTEST_SKIP() << "the test process already runs at nice " << thread_nice();
    EXPECT_EQ(in_child([]() -> int {
                  const int own = thread_nice();
                  std::atomic<bool> stop{false};
                  std::atomic<int> kept_tid{0};
                  std::atomic<int> kept_nice{-1};
                  std::thread kept([&] {
                      kept_tid = gdnav::dds::current_tid();
                      while (!stop) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                      kept_nice = thread_nice();
                  });
                  while (kept_tid == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                  if (!lower_cpu_priority(12, kept_tid).empty()) return 2;
                  if (thread_nice() != 12) return 3;
                  stop = true;
                  kept.join();
                  if (kept_nice != own) return 4;
                  return 0;
              }),
              0);
}

TEST(ProcessPriority, OnlyEverRaisesAndRejectsValuesOutside1To19) {
    const int own = thread_nice();
    if (own >= 15) GTEST_SKIP() << "the test process already runs at nice " << own;
    EXPECT_EQ(in_child([]() -> int {
                  if (!lower_cpu_priority(15).empty()) return 1;
                  if (!lower_cpu_priority(5).empty()) return 2;  // a nicer thread keeps its value
                  if (thread_nice() != 15) return 3;
                  return 0;
              }),
              0);
    EXPECT_NE(lower_cpu_priority(0).find("outside 1..19"), std::string::npos);
    EXPECT_NE(lower_cpu_priority(20).find("outside 1..19"), std::string::npos);
    EXPECT_EQ(thread_nice(), own);  // the test process itself was never changed
}
