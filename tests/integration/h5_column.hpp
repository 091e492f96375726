#pragma once
// One column of a run.h5 table of nav_recorder (/error, /estimate, /truth: rows of named doubles), for tests.
#include <filesystem>
#include <vector>

namespace gdnav::testing {

// Every row's value of the double field `name` of table `table`; empty when the file, table or field is missing.
std::vector<double> h5_column(const std::filesystem::path& h5, const char* table, const char* name);

}  // namespace gdnav::testing
