#pragma once
// Folders the tests write runs into.
#include <filesystem>
#include <string>

namespace gdnav::testing {

// A fresh, empty temporary directory for one test (unique per process and call).
std::filesystem::path temp_dir(const std::string& tag);
// The folder of run `i` of the Monte Carlo batch in `batch` (gdnav montecarlo --out batch).
std::string run_dir(const std::filesystem::path& batch, int i);

}  // namespace gdnav::testing
