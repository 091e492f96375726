#pragma once
// gdnav report / the end of gdnav montecarlo: the directories of one batch (its shards) merged into one block
// (batch_merge.hpp); aggregate a batch directory's per-run metrics into the paper's tables
// (report/tables.md, aggregate.yaml, runs.csv), draw the figures with tools/report/report.py and write the flight
// review pages with tools/report/review.py (Debian's /usr/bin/python3 with matplotlib, h5py, numpy and plotly;
// override with $GDNAV_PYTHON and $GDNAV_REPORT_SCRIPT).
#include <filesystem>
#include <string>
#include <vector>

namespace gdnav::launch::batch {

struct ReportOptions {
    bool figures{true};
    bool review{true};  // with the figures: the HTML flight review pages (tools/report/review.py, python3-plotly)
    std::filesystem::path out;  // default: <first dir>/report
};

// Returns 0 when the tables (and figures, if asked) were written; the count of complete runs per batch in `runs`.
int write_batch_report(const std::vector<std::filesystem::path>& batch_dirs, const ReportOptions& o,
                       std::vector<std::size_t>* runs = nullptr);

// Runs a Python tool of tools/report/ (report.py: PNG figures; review.py: HTML flight review pages; compare.py:
// gdnav compare) with Debian's /usr/bin/python3 ($GDNAV_PYTHON); $GDNAV_REPORT_SCRIPT names report.py elsewhere, the
// other tools beside it. Returns the tool's exit code (1 when it cannot start), logged when non-zero and log_failure.
int run_report_tool(const std::string& name, std::vector<std::string> args, bool log_failure = true);

}  // namespace gdnav::launch::batch
