#pragma once
// `gdnav bench`: runs the same scenario in each layout and measures steps/s and the real-time factor, the cost of
// each component per step (direct layout), and the Monte Carlo throughput of scenarios #1 and #2 (runs per minute in
// the direct layout, from a small batch); `security` adds the composed layout with DDS Security on. The figures are
// printed as tables (bench_tables) and may be written as JSON (bench_json.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include "framework/registry.hpp"
#include "launch/bench/bench_json.hpp"

namespace gdnav::launch::bench {

struct BenchOptions {
    std::string scenario{"default"};
    std::uint64_t steps{20000};
    std::vector<std::string> layouts{"direct", "composed", "distributed"};
    std::uint64_t mc_runs{2};   // runs of each paper scenario in the Monte Carlo measurement (0: none)
    std::uint64_t mc_steps{0};  // steps of each of those runs (0: full length)
    unsigned mc_jobs{2};
    std::string json;  // write the figures to this file
    std::string security;  // DDS Security directory: also measure the composed layout with it ("composed+security")
    std::string log_level{"info"};  // of the Monte Carlo runs
};

// Measures every figure of the session (work files in a temporary folder, removed at the end). Throws when a
// layout's run fails (std::runtime_error naming the layout) or the Monte Carlo batch fails.
BenchFigures measure_bench(const BenchOptions& o, const framework::ComponentRegistry& reg);

// The figures as the text tables `gdnav bench` prints.
std::string bench_tables(const BenchFigures& f, const BenchOptions& o);

// Writes bench_json(f, machine_info()) to `file`; throws std::runtime_error when it cannot.
void write_bench_json(const BenchFigures& f, const std::string& file);

}  // namespace gdnav::launch::bench
