// gdnav host --plan PLAN --name H, and gdnav run --plan PLAN (the clock's host): one host's slice of a deployment
// plan (launch/plan/plan.hpp, docs/deployment.md "Plans"). Every host resolves the same run from the plan (same
// scenario, seed, domain and overrides), writes the plan's Fast DDS XML (discovery from the plan, no hand-edited
// addresses) into its output directory, starts the discovery server(s) the plan puts on it, and starts and
// supervises its own members (exit codes, clean-up, Ctrl-C) through the launcher.
#include "commands_plan.hpp"

#include <fstream>
#include <memory>

#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

#include "launch/plan/plan.hpp"
#include "launch/launcher.hpp"
#include "scenario_overrides.hpp"

namespace gdnav::app {

namespace fs = std::filesystem;
using namespace gdnav::runtime;

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
    const deploy::PlanHost& host = a.host.empty() ? plan.clock_host() : plan.host(a.host);
    const fs::path out = a.out.empty() ? fs::path("out/plan") / host.name : fs::path(a.out);
    fs::create_directories(out);
    const fs::path xml = fs::absolute(out / "dds_plan.xml");
    std::ofstream(xml) << deploy::plan_profile_xml(plan);

    // The run: the scenario with the plan's run keys, domain and profile (same on every host).
    const fs::path scenario_file = plan_scenario_file(plan);
    YAML::Node doc = YAML::LoadFile(scenario_file.string());
    if (plan.run_overrides)
        for (const auto& kv : plan.run_overrides) doc["run"][kv.first.as<std::string>()] = YAML::Clone(kv.second);
    doc["run"]["dds_profile"] = xml.string();
    RunOverrides o;
    o.domain_id = plan.domain_id;
    o.out_dir = out.string();
    if (plan.seed) o.seed = *plan.seed;
    if (a.steps > 0) o.steps = a.steps;
    YAML::Emitter em;
    em.SetDoublePrecision(17);
    em << doc;
    RunConfig rc = RunConfig::parse(em.c_str(), scenario_file.string(), o);
    if (!a.rw.empty()) rc = apply_run_rewrites(rc, a.rw, ctx.registry);
    std::vector<std::string> names;
    for (const auto& m : rc.members) names.push_back(m.name);
    plan.check_members(names, rc.external);

    LaunchOptions lo;
    lo.layout = host.process;
    lo.log_level = ctx.log_level;
    lo.slice = true;
    lo.start_clock = host.clock;
    for (const auto& m : host.members)
        if (std::find(names.begin(), names.end(), m) != names.end()) lo.only.push_back(m);
    int id = 0;
    for (const std::string* s : {&plan.server_host, &plan.backup_host}) {
        if (!s->empty() && *s == host.name)
            lo.services.push_back({"discovery server " + std::to_string(id),
                                   {"/usr/bin/fast-discovery-server", "-i", std::to_string(id), "-l", host.address,
                                    "-p", std::to_string(plan.server_port + id)}});
        ++id;
    }
    std::string elsewhere;
    for (const auto& h : plan.hosts)
        if (h.name != host.name) {
            std::string ms;
            for (const auto& m : h.members) ms += (ms.empty() ? "" : ",") + m;
            elsewhere += (elsewhere.empty() ? "" : "; ") + h.name + " (" + h.address + "): " +
                         (h.clock ? std::string("clock") + (ms.empty() ? "" : ",") : std::string()) + ms;
        }
    std::string mine;
    for (const auto& m : lo.only) mine += (mine.empty() ? "" : ",") + m;
    spdlog::info("plan {}: host {} ({}) runs {}{} as {}, discovery {}, DDS domain {}; other hosts: {}",
                 plan.file.string(), host.name, host.address, host.clock ? "the clock, " : "", mine, host.process,
                 plan.discovery, plan.domain_id, elsewhere.empty() ? "none" : elsewhere);
    return launch_run(std::move(rc), ctx.registry, lo);
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

}  // namespace gdnav::app
