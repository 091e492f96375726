#pragma once
// Members that gdnav starts for every run (`run.members`, `--member NAME=SPEC`; docs/external.md, "Members started
// by gdnav"):
//
//   run:
//     members:
//       nav_att: {command: [python3, my_filter.py, --x-gain, "0.02"], cwd: work, env: {OMP_NUM_THREADS: "1"}}
//       nav_pos: {python: {file: my_filter.py, class: PosFilter}}   # a Python class, in-process (docs/python.md)
//
// A `command` member is a process the launcher starts and supervises like a built-in member; for the clock it is
// an external member (it joins through the lockstep protocol), so a name may replace a configured component or add
// a new member, as in `run.external`.
// A `python` member is hosted by gdnav itself: RunConfig::parse first rewrites such an entry as the component NAME
// of type `python_member` ({file: ABSOLUTE PATH, class: C, replaces: T} where T is the type of the configured
// component NAME it stands in for, if any) and removes it from `run.members`, so the resolved run.yaml that every
// process of the run reads holds the component itself; only `command` entries remain for the launcher.
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "config/config.hpp"
#include "framework/compat.hpp"

namespace gdnav::framework {

inline constexpr const char* kPythonMemberType = "python_member";

// Rewrites `root` (a run document, overrides applied): each `python` entry of run.members becomes a component, as
// above. Throws ConfigError naming the file and key.
void apply_inprocess_members(YAML::Node& root, const std::string& origin);

struct StartedMember {
    std::string name;
    // argv of a process member, with the placeholders {domain}, {run}, {out}, {security} not yet substituted;
    // empty for the in-process Python form.
    std::vector<std::string> command;
    std::string cwd;                                         // "" = the working directory of gdnav
    std::vector<std::pair<std::string, std::string>> env;   // extra environment (values may hold placeholders)
    std::string python_file, python_class;                  // the in-process Python form
    [[nodiscard]] bool in_process() const { return command.empty(); }
};

// The environment variables gdnav sets for a process member (docs/external.md); `env:` may not set them.
inline const std::vector<std::string>& member_env_names() {
    static const std::vector<std::string> names{"GDNAV_MEMBER", "GDNAV_DOMAIN",   "GDNAV_RUN",
                                                "GDNAV_OUT",    "GDNAV_SECURITY", "GDNAV_DDS_PROFILE"};
    return names;
}

// Splits a command line into words by shell-like rules, without running a shell: blanks separate words; '...'
// keeps everything literally; "..." keeps everything but \" \\ \$ \` (backslash-escaped); outside quotes a
// backslash keeps the next character. No expansion of variables, globs or ~. Throws ConfigError on an open quote.
std::vector<std::string> split_command_line(const std::string& text, const std::string& what);

// `--member NAME=SPEC` as the `run.members` entry it stands for: {NAME, node}. SPEC is `python:FILE.py:CLASS` or
// a command line (split_command_line). Throws ConfigError (one line naming the option) on a malformed spec.
std::pair<std::string, YAML::Node> member_option_node(const std::string& option);
// Adds the `--member` options to a document's `run.members` (a name given again replaces the file's entry); the
// commands build the document this way before RunConfig::parse.
void add_member_options(YAML::Node& root, const std::vector<std::string>& options);

// Reads `run.members` (each key read, so the section's finish() checks them). RunConfig::parse reads it: each
// process member is added to RunConfig::external (the clock waits for it as for any external member).
std::vector<StartedMember> read_started_members(const config::Config& run);

class RunConfig;
// The run.members of a parsed run configuration (read again from its resolved document).
std::vector<StartedMember> started_members(const RunConfig& rc);
// The entry named `name`, or nullptr.
const StartedMember* find_started(const std::vector<StartedMember>& members, const std::string& name);

}  // namespace gdnav::framework
