#pragma once
// The cause of a failed run, told to the launcher on a pipe: a channel that needs no disk.
//
// A full disk takes the run's own files with it (clock_summary.yaml, the members' logs), so a process that fails
// for a reason the run's last line must name (an output file it could not write, the clock's abort reason when it
// cannot write clock_summary.yaml) also writes that reason, one line, to the pipe the launcher hands down in the
// environment variable kCauseFdEnv. Lines shorter than PIPE_BUF reach the pipe whole even when several processes
// write at once. docs/runtime.md, "Exit codes".
#include <string>
#include <string_view>
#include <vector>

#include "dds/compat.hpp"

namespace gdnav::dds {

inline constexpr const char* kCauseFdEnv = "GDNAV_CAUSE_FD";

// Writes LINE (cut to one line of at most 1000 characters) to the launcher's cause pipe; nothing when this process
// was not started with one.
void tell_launcher(std::string_view line);

// The launcher's end of the channel: a pipe whose write end the children inherit (named in kCauseFdEnv while it
// lives), read without blocking once they have ended.
class CausePipe {
public:
    CausePipe();
    ~CausePipe();
    CausePipe(const CausePipe&) = delete;
    CausePipe& operator=(const CausePipe&) = delete;
    // Every line the children wrote so far, in the order they arrived.
    [[nodiscard]] std::vector<std::string> read_lines();

private:
    int read_fd_{-1};
    int write_fd_{-1};
    std::string pending_;
};

}  // namespace gdnav::dds
