#pragma once
// `gdnav bench`: runs the same scenario in each layout and prints steps/s and the real-time factor as a table.
#include <string>
#include <vector>

#include "runtime/registry.hpp"

namespace gdnav::app {

struct BenchArgs {
    std::string scenario{"default"};
    std::uint64_t steps{20000};
    std::vector<std::string> layouts{"direct", "composed", "distributed"};
};

int run_bench(const BenchArgs& a, const runtime::ComponentRegistry& reg);

}  // namespace gdnav::app
