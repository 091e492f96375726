// runtime/process_exit: a process whose tear-down does not end leaves with the run's exit code once the bound is
// over. Each case runs in a forked child so that the test process goes on.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "dds/process/process_exit.hpp"

namespace {

// The exit code of a child running `body`, or -1 when it ended otherwise.
int child_exit_code(void (*body)()) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        body();
        ::_exit(99);
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST(ProcessExit, ATearDownThatHangsEndsWithTheRunsExitCode) {
    // The "tear-down" waits far longer than the bound (a deadlock stands in for it); the bound ends the process with
    // the code it was given, not the 99 the child would end with after the wait.
    EXPECT_EQ(child_exit_code([] {
                  gdnav::dds::bound_teardown(7, 0.2);
                  std::this_thread::sleep_for(std::chrono::seconds(30));
              }),
              7);
}

TEST(ProcessExit, ATearDownWithinTheBoundEndsAsItWould) {
    EXPECT_EQ(child_exit_code([] {
                  gdnav::dds::bound_teardown(7, 30.0);
                  std::this_thread::sleep_for(std::chrono::milliseconds(10));
              }),
              99);
}
