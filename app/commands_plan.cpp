// gdnav host --plan PLAN --name H, and gdnav run --plan PLAN (the clock's host): one host's slice of a deployment
// plan (launch/plan/plan_host.hpp).
#include "commands_plan.hpp"

#include <memory>

#include <spdlog/spdlog.h>

#include "launch/launcher.hpp"
#include "launch/plan/plan_host.hpp"
#include "scenario_overrides.hpp"

namespace gdnav::cli {

namespace fs = std::filesystem;
using namespace gdnav::framework;
using namespace gdnav::launch;

namespace {

fs::path plan_scenario_file(const deploy::Plan& plan) {
    const fs::path s = plan.scenario;
    const bool file_like = s.has_extension() || s.has_parent_path();
    if (file_like && s.is_relative()) return plan.file.parent_path() / s;
    return resolve_scenario(scenario::scenario_alias(plan.scenario));
}

}  // namespace

int run_plan_host(const PlanHostArgs& a, const CliContext& ctx) {
    const deploy::Plan plan = deploy::Plan::load(a.plan);
    deploy::PlanHostRequest req;
    req.host = a.host;
    req.out = a.out;
    req.steps = a.steps;
    req.rw = a.rw;
    req.log_level = ctx.log_level;
    deploy::PlanHostRun r = deploy::plan_host_run(plan, req, plan_scenario_file(plan), ctx.registry);
    spdlog::info("{}", r.summary);
    return launch_run(std::move(r.rc), ctx.registry, r.lo);
}

CLI::App* add_host_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    auto a = std::make_shared<PlanHostArgs>();
    auto* sub = app.add_subcommand("host", "run one host's slice of a deployment plan (docs/deployment.md)");
    sub->add_option("--plan", a->plan, "deployment plan (deploy/plans/*.yaml)")->required()->check(CLI::ExistingFile);
    sub->add_option("--name", a->host, "this host's name in the plan")->required();
    sub->add_option("--out", a->out, "output directory (default out/plan/<host>)");
    sub->add_option("--steps", a->steps, "override the number of steps (give the same on every host)");
    sub->add_option("--record", a->rw.record, "record these topics (place `recorder` on a host of the plan)")
        ->delimiter(',');
    run = [a, &ctx]() {
        setup_logging("gdnav", ctx.log_level);
        return run_plan_host(*a, ctx);
    };
    return sub;
}

}  // namespace gdnav::cli
