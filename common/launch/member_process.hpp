#pragma once
// The process members of a run (`run.members` with a `command`, framework/run_members.hpp): resolved and checked
// before anything starts, then started by the launcher as supervised children with their output in
// <out>/logs/NAME.log, the run's DDS domain, run index, folder and security material in their argv (placeholders)
// and environment (docs/external.md, "Members started by gdnav").
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "framework/run_config.hpp"
#include "framework/run_members.hpp"

namespace gdnav::launch {

struct MemberProcess {
    std::string name;
    std::filesystem::path exe;      // the executable, resolved (PATH or relative to cwd)
    std::vector<std::string> argv;  // placeholders substituted; argv[0] as given
    std::filesystem::path cwd;      // absolute
    std::filesystem::path file;     // the file it runs: an interpreter's script, else exe
    std::string sha256;             // of `file`
    std::vector<std::pair<std::string, std::string>> env;  // set on top of gdnav's environment
};

// Refuses what this layout cannot run (a process member in `direct`; the in-process Python form, not built in this
// version), one line naming the key. Nothing else is checked here.
void check_started_members(const framework::RunConfig& rc, const std::string& layout);

// Every process member of rc with rc.domain_id, run index, out_dir and security substituted. Throws ConfigError
// naming run.members.NAME when a working directory or the executable is missing.
std::vector<MemberProcess> resolve_member_processes(const framework::RunConfig& rc);

// Starts the member (same process group as the launcher, ended with it) with stdout and stderr appended to
// <out_dir>/logs/NAME.log.
pid_t start_member_process(const MemberProcess& m, const std::filesystem::path& out_dir);

// Its entry of processes.yaml: `NAME: {pid: P, command: [...], cwd: D, executable: E, file: F, sha256: H}`.
std::string member_process_record(const MemberProcess& m, pid_t pid);

// Lowercase hex SHA-256 of a file's bytes (OpenSSL); throws std::runtime_error when it cannot be read.
std::string sha256_of_file(const std::filesystem::path& file);

}  // namespace gdnav::launch
