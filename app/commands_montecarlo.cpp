// gdnav montecarlo: a batch (or --shard I/N of it) run by launch/batch/batch_runner.hpp into its directory
// (launch/batch/batch_dir.hpp), then aggregated (launch/batch/batch_report.hpp); --mpi spreads the shards over MPI
// ranks (montecarlo_mpi.cpp).
#include <memory>

#include <spdlog/spdlog.h>

#include "commands.hpp"
#include "commands_scenario.hpp"
#include "framework/lockstep.hpp"
#include "framework/run_members.hpp"
#include "launch/batch/batch_report.hpp"
#include "montecarlo.hpp"

namespace gdnav::cli {

namespace fs = std::filesystem;
using namespace gdnav::framework;

launch::batch::BatchSpec batch_spec(const McArgs& a, const CliContext& ctx) {
    const ScenarioDocument s = load_scenario_document(a.batch.scenario, a.o);
    launch::batch::BatchSpec b = a.batch;
    b.file = s.file;
    b.doc = s.doc;
    add_member_options(b.doc, a.members);
    b.log_level = ctx.log_level;
    return b;
}

int run_batch_shard(const McArgs& a, const CliContext& ctx, const launch::batch::Shard& shard) {
    return run_batch_shard(batch_spec(a, ctx), ctx.registry, shard);
}

int run_montecarlo(const McArgs& a, const CliContext& ctx) {
    if (a.mpi) {
#ifdef GDNAV_HAVE_MPI
        if (!a.shard.empty()) throw config::ConfigError("montecarlo: --mpi and --shard exclude each other");
        return run_montecarlo_mpi(a, ctx);
#else
        throw config::ConfigError("montecarlo: --mpi: this gdnav was built without MPI (install libopenmpi-dev and "
                                  "rebuild, see docs/montecarlo.md)");
#endif
    }
    const launch::batch::Shard shard = a.shard.empty() ? launch::batch::Shard{} : launch::batch::parse_shard(a.shard);
    int code = run_batch_shard(a, ctx, shard);
    // Interrupted, or stopped on a full disk (a report could not be written either): the batch's last line stands.
    if (code == kExitInterrupted || code == kExitWriteFailed) return code;
    if (!shard.whole()) {
        spdlog::info("montecarlo: shard {}/{} done; aggregate the shards with: gdnav report DIR [DIR ...]", shard.index,
                     shard.count);
    } else if (!a.no_report) {
        launch::batch::ReportOptions ro;
        ro.figures = !a.no_figures;
        const int rc = launch::batch::write_batch_report({fs::absolute(a.batch.out)}, ro);
        if (rc != 0) code = code ? code : rc;
    }
    return code;
}

CLI::App* add_montecarlo_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    auto a = std::make_shared<McArgs>();
    auto* sub = app.add_subcommand("montecarlo", "run a Monte Carlo batch (parallel, resumable) and aggregate it");
    sub->add_option("--shard", a->shard, "run only shard I of N (I/N, 1-based: runs first+k with k mod N = I-1)");
    sub->add_flag("--mpi", a->mpi, "under mpirun: the ranks share the runs, rank 0 writes the report");
    sub->add_option("--scenario", a->batch.scenario, "1, 2 (paper scenarios), a scenario name or a YAML file");
    sub->add_option("--runs", a->batch.runs, "number of runs")->check(CLI::Range(1, 1000000));
    sub->add_option("--first", a->batch.first, "index of the first run");
    sub->add_option("--seed", a->batch.seed, "master seed (default: the scenario file's)");
    sub->add_option("--jobs,-j", a->batch.jobs, "runs in parallel")->check(CLI::Range(1, 256));
    sub->add_option("--layout", a->batch.layout, "direct | composed | distributed")
        ->check(CLI::IsMember({"direct", "composed", "distributed"}));
    sub->add_option("--out", a->batch.out, "batch directory")->required();
    sub->add_option("--domain", a->batch.domain,
                    "DDS domain of the first parallel slot: slot k of --jobs uses D+k (default: each run takes one "
                    "no other run of this host uses)")
        ->check(CLI::Range(0, 232));
    sub->add_option("--steps", a->batch.steps, "override the number of steps of every run");
    sub->add_option("--set", a->o.sets, "override a key: path.to.key=value (YAML value; ~ removes)");
    sub->add_option("--grade", a->o.grades, "sensor grade for every group (NAME) or one group (GROUP=NAME)");
    sub->add_option("--variant", a->o.variants, "navigation variant NAME (nav_att, nav_pos) or COMPONENT=NAME");
    sub->add_option("--member", a->members,
                    "a member gdnav starts in every run: NAME=COMMAND or NAME=python:FILE.py:CLASS (repeatable; "
                    "docs/montecarlo.md)");
    sub->add_flag("--no-report", a->no_report, "do not aggregate at the end");
    sub->add_flag("--no-figures", a->no_figures, "aggregate tables only");
    run = [a, sub, &ctx]() {
        setup_logging("gdnav", ctx.log_level);
        a->batch.seed_given = sub->count("--seed") > 0;
        return run_montecarlo(*a, ctx);
    };
    return sub;
}

}  // namespace gdnav::cli
