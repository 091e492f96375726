#pragma once
// `gdnav bench`: runs the same scenario in each layout and prints steps/s and the real-time factor as a table, the
// cost of each component per step (direct layout), and the Monte Carlo throughput of scenarios #1 and #2 (runs per
// minute in the direct layout, from a small batch); --security DIR adds the composed layout with DDS Security on;
// --json FILE writes the same figures (bench_json.hpp).
#include <string>
#include <vector>

#include "command.hpp"

namespace gdnav::app {

struct BenchArgs {
    std::string scenario{"default"};
    std::uint64_t steps{20000};
    std::vector<std::string> layouts{"direct", "composed", "distributed"};
    std::uint64_t mc_runs{2};   // runs of each paper scenario in the Monte Carlo measurement (0: none)
    std::uint64_t mc_steps{0};  // steps of each of those runs (0: full length)
    unsigned mc_jobs{2};
    std::string json;  // write the figures to this file
    std::string security;  // DDS Security directory: also measure the composed layout with it ("composed+security")
};

int run_bench(const BenchArgs& a, const CliContext& ctx);

}  // namespace gdnav::app
