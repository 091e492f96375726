#pragma once
// Members that the user gives in `run.members` and that gdnav hosts itself, inside its own processes:
//
//   run:
//     members:
//       nav_att: {python: {file: my_filter.py, class: MyFilter}}   # a Python class, in-process (docs/python.md)
//
// Such an entry becomes the component NAME of type `python_member` ({file: ABSOLUTE PATH, class: C, replaces: T}
// where T is the type of the configured component NAME it stands in for, if any) and leaves `run.members`, so the
// resolved run.yaml that every process of the run reads holds the component itself. Entries of other kinds are left.
#include <string>

#include <yaml-cpp/yaml.h>

namespace gdnav::runtime {

inline constexpr const char* kPythonMemberType = "python_member";

// Rewrites `root` (a run document, overrides applied) as above; throws ConfigError naming the file and key.
void apply_inprocess_members(YAML::Node& root, const std::string& origin);

}  // namespace gdnav::runtime
