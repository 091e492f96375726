#pragma once
// gdnav montecarlo's options, shared by the command (commands_montecarlo.cpp), the MPI launcher (montecarlo_mpi.cpp)
// and the benchmark (bench.cpp); the batch itself is run by launch/batch/batch_runner.hpp.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "launch/batch/batch_runner.hpp"
#include "command.hpp"
#include "scenario_overrides.hpp"

namespace gdnav::cli {

struct McArgs {
    // The options that are the batch's as they are (scenario, runs, first, seed, seed_given, jobs, layout, domain,
    // out, steps); batch_spec() adds the scenario document and the log level.
    launch::batch::BatchSpec batch{.scenario = "1"};
    scenario::Overrides o;
    std::vector<std::string> members;  // --member NAME=SPEC (run.members of every run)
    bool no_report{false};
    bool no_figures{false};
    std::string shard;  // "I/N" (empty: the whole batch)
    bool mpi{false};
};

// The batch of these options: the scenario document with the overrides applied, and this process's log level.
launch::batch::BatchSpec batch_spec(const McArgs& a, const CliContext& ctx);
// run_batch_shard (batch_runner.hpp) of these options. No report (see write_batch_report).
int run_batch_shard(const McArgs& a, const CliContext& ctx, const launch::batch::Shard& s);

// The whole command: the batch or its --shard, then (whole batch only, unless --no-report) the report.
int run_montecarlo(const McArgs& a, const CliContext& ctx);

#ifdef GDNAV_HAVE_MPI
// mpirun -np N gdnav montecarlo --mpi ...: rank r runs shard r+1 of N; rank 0 gathers the ranks' metrics and writes
// the report (montecarlo_mpi.cpp). Returns the rank's exit code (rank 0: the batch's).
int run_montecarlo_mpi(const McArgs& a, const CliContext& ctx);
#endif

}  // namespace gdnav::cli
