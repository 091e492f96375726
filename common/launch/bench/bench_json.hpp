#pragma once
// gdnav bench --json FILE: the figures of one bench session as a JSON document, with the machine (CPU model, core
// count, load), the date and the git commit, so sessions can be tracked over time (docs/runtime.md, "Benchmarks").
#include <string>
#include <utility>
#include <vector>

namespace gdnav::launch::bench {

struct BenchLayoutFigure {
    std::string layout;
    double steps_per_s{0.0};
    double x_real_time{0.0};
};

struct BenchMcFigure {
    std::string scenario;          // "1", "2"
    std::uint64_t runs{0};         // runs measured
    std::uint64_t steps_run{0};    // steps of each measured run
    std::uint64_t steps_full{0};   // steps of a full-length run
    double wall_s{0.0};            // wall time of the measured batch (no report)
    double runs_per_minute{0.0};   // full-length runs, extrapolated
};

struct BenchFigures {
    std::string scenario;
    std::uint64_t steps{0};
    double dt_s{0.0};
    std::vector<BenchLayoutFigure> layouts;
    std::vector<std::pair<std::string, double>> component_us;  // direct layout, per step
    unsigned mc_jobs{0};
    std::vector<BenchMcFigure> montecarlo;
};

struct MachineInfo {
    std::string cpu_model;  // /proc/cpuinfo "model name"
    unsigned cores{0};      // logical CPUs
    double load_1min{0.0};  // /proc/loadavg at the end of the session
    std::string git_commit; // "unknown" outside a git checkout
    bool git_dirty{false};  // tracked files differ from the commit
    std::string date_utc;   // ISO 8601
};
MachineInfo machine_info();

std::string bench_json(const BenchFigures& f, const MachineInfo& m);

}  // namespace gdnav::launch::bench
