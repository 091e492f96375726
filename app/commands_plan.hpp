#pragma once
// The options of `gdnav host --plan P --name H` and `gdnav run --plan P` (the clock's host): one host's slice of a
// deployment plan (launch/plan/plan_host.hpp).
#include <cstdint>
#include <string>

#include "command.hpp"
#include "launch/run_rewrites.hpp"

namespace gdnav::cli {

struct PlanHostArgs {
    std::string plan;
    std::string host;  // empty: the host with the clock
    std::string out;
    std::uint64_t steps{0};
    launch::RunRewrites rw;  // --record only
};

int run_plan_host(const PlanHostArgs& a, const CliContext& ctx);

}  // namespace gdnav::cli
