// Subcommands of the runtime: run, component, clock, validate, list, bench.
#include "commands.hpp"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>

#include <spdlog/spdlog.h>

#include "commands_plan.hpp"
#include "commands_scenario.hpp"
#include "framework/run_members.hpp"
#include "launch/bench/bench.hpp"
#include "launch/run_rewrites.hpp"
#include "dds/clock/clock.hpp"
#include "dds/host/dds_host.hpp"
#include "framework/graph.hpp"
#include "launch/launcher.hpp"
#include "framework/lockstep.hpp"
#include "dds/process/process_exit.hpp"
#include "dds/process/process_signals.hpp"
#include "framework/topic_types.hpp"

namespace gdnav::cli {

using namespace gdnav::framework;
using namespace gdnav::dds;
using namespace gdnav::launch;

namespace {

// The clock's summary and faults.yaml are written when Clock::run returns; what follows is DDS tear-down only, which
// normally takes well under a second.
constexpr double kClockTeardownDeadlineS = 10.0;
// A member's tear-down bound: member_timeout_s plus this, below the launcher's member_timeout_s + 3 s.
constexpr double kMemberTeardownMarginS = 1.0;

struct RunArgs {
    std::string scenario{"default"};
    std::uint64_t seed{1};
    std::uint64_t run_index{0};
    std::string layout{"distributed"};
    std::string out;
    double realtime{0.0};
    std::uint64_t steps{0};
    int domain{-1};
    std::vector<std::string> external;
    std::vector<std::string> members;
    double join_timeout_s{0.0};
    std::string faults_file;
    std::string security;
    std::string plan;
    RunRewrites rw;
    scenario::Overrides o;
};

void add_run_options(CLI::App* sub, RunArgs* a) {
    sub->add_option("--scenario", a->scenario, "scenario name (config/scenarios/<name>.yaml) or YAML file");
    sub->add_option("--seed", a->seed, "master seed");
    sub->add_option("--run", a->run_index, "run index inside a batch");
    sub->add_option("--layout", a->layout, "direct | composed | distributed")
        ->check(CLI::IsMember({"direct", "composed", "distributed"}));
    sub->add_option("--out", a->out, "output directory");
    sub->add_option("--realtime", a->realtime, "pace to wall time x FACTOR (0 = as fast as possible)")
        ->check(CLI::Range(0.0, 1e6));
    sub->add_option("--steps", a->steps, "override the number of steps");
    sub->add_option("--domain", a->domain, "DDS domain id (default: the lowest one no other run of this host uses, docs/runtime.md)")
        ->check(CLI::Range(0, 232));
    sub->add_option("--set", a->o.sets, "override a key: path.to.key=value (YAML value; ~ removes)");
    sub->add_option("--grade", a->o.grades, "sensor grade for every group (NAME) or one group (GROUP=NAME)");
    sub->add_option("--variant", a->o.variants, "navigation variant NAME (nav_att, nav_pos) or COMPONENT=NAME");
    sub->add_option("--external", a->external,
                    "members run outside gdnav (NAME[,NAME...]): not started, waited for (docs/protocol.md)")
        ->delimiter(',');
    sub->add_option("--member", a->members,
                    "a member gdnav starts: NAME=COMMAND or NAME=python:FILE.py:CLASS (run.members; repeatable; "
                    "docs/external.md)");
    sub->add_option("--join-timeout", a->join_timeout_s, "seconds to wait for --external members (run.join_timeout_s)")
        ->check(CLI::Range(1.0, 86400.0));
    sub->add_option("--faults", a->faults_file,
                    "apply the fault list of this file instead of the scenario's (e.g. a run's <out>/faults.yaml)");
    sub->add_option("--security", a->security,
                    "DDS Security directory made by `gdnav pki init` (run.security; docs/deployment.md)");
    sub->add_option("--plan", a->plan, "deployment plan: run the clock host's slice (docs/deployment.md)")
        ->check(CLI::ExistingFile);
    sub->add_option("--record", a->rw.record, "record these topics (TOPIC[,TOPIC...]; default = the five sensor topics; or all; plus `viewer` for the viewer channels, docs/viewing.md) to <out>/record/run.mcap")
        ->delimiter(',');
    sub->add_option("--replay", a->rw.replay_dir, "replay topics recorded in this run directory (docs/replay.md)");
    sub->add_option("--topics", a->rw.replay_topics, "topics to replay with --replay (TOPIC[,TOPIC...])")
        ->delimiter(',');
    sub->add_option("--live", a->rw.live_port,
                    "serve the run live to Foxglove on ws://127.0.0.1:PORT (default 8765; docs/viewing.md)")
        ->expected(0, 1);
    sub->add_option("--live-bind", a->rw.live_bind, "address the live view listens on (default 127.0.0.1)");
    sub->add_option("--live-decimation", a->rw.live_decimation, "stream every N-th step of the topics to the live view (default 10: 10 Hz at dt = 0.01 s)")
        ->check(CLI::Range(std::uint64_t{1}, std::uint64_t{1000000}));
    sub->add_option("--live-topics", a->rw.live_topics, "topics of the live view (TOPIC[,TOPIC...], `viewer` for the viewer channels; default: all,viewer)")
        ->delimiter(',');
}

// gdnav run --plan: the clock host's slice of the plan; the plan names what the other options would.
int run_with_plan(const RunArgs& a, const CLI::App& sub, const CliContext& ctx) {
    for (const char* opt : {"--scenario", "--seed", "--run", "--layout", "--domain", "--replay", "--external",
                            "--member", "--security", "--set", "--grade", "--variant", "--faults", "--realtime"})
        if (sub.count(opt))
            throw config::ConfigError(std::string("config error: --plan and ") + opt +
                                      ": the plan names the scenario, seed, domain and layout of each host");
    for (const char* opt : {"--live", "--live-bind", "--live-decimation", "--live-topics"})
        if (sub.count(opt))
            throw config::ConfigError(std::string("config error: --plan and ") + opt +
                                      ": give the plan's scenario a `live` member instead (docs/viewing.md)");
    PlanHostArgs pa;
    pa.plan = a.plan;
    pa.out = a.out;
    pa.steps = a.steps;
    pa.rw.record = a.rw.record;
    return run_plan_host(pa, ctx);
}

// The run configuration of the command line: the scenario (or, with --replay and no --scenario, the replayed run's)
// with the overrides.
RunConfig run_config_of(const RunArgs& a, const CLI::App& sub) {
    RunOverrides o;
    if (sub.count("--seed")) o.seed = a.seed;
    if (sub.count("--run")) o.run_index = a.run_index;
    if (!a.out.empty()) o.out_dir = a.out;
    if (sub.count("--realtime")) o.realtime = a.realtime;
    if (a.steps > 0) o.steps = a.steps;
    if (a.domain >= 0) o.domain_id = a.domain;
    if (!a.external.empty()) o.external = a.external;
    if (sub.count("--join-timeout")) o.join_timeout_s = a.join_timeout_s;
    if (!a.faults_file.empty()) o.faults_file = a.faults_file;
    if (!a.security.empty()) o.security = a.security;
    // With --replay and no --scenario, the replayed run's own configuration is the base.
    const bool replay_base = !a.rw.replay_dir.empty() && !sub.count("--scenario");
    RunConfig rc = [&] {
        if (replay_base) {
            if (!a.o.empty()) throw config::ConfigError("config error: --set/--grade/--variant need --scenario with --replay");
            const std::filesystem::path file = std::filesystem::path(a.rw.replay_dir) / "run.yaml";
            if (a.members.empty()) return RunConfig::load(file, o);
            YAML::Node doc = YAML::Clone(config::Config::load(file).node());
            add_member_options(doc, a.members);
            return RunConfig::parse(document_text(doc), file.string(), o);
        }
        if (a.o.empty() && a.members.empty())
            return RunConfig::load(resolve_scenario(scenario::scenario_alias(a.scenario)), o);
        // Overrides apply to the scenario document before its generator runs (as in gdnav scenario/montecarlo).
        ScenarioDocument s = load_scenario_document(a.scenario, a.o);
        add_member_options(s.doc, a.members);
        return RunConfig::parse(document_text(s.doc), s.file.string(), o);
    }();
    return rc;
}

}  // namespace

CLI::App* add_run_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    auto a = std::make_shared<RunArgs>();
    auto* sub = app.add_subcommand("run", "run one simulation in a layout, supervising all its processes");
    add_run_options(sub, a.get());
    run = [a, sub, &ctx]() {
        setup_logging("gdnav", ctx.log_level);
        if (!a->plan.empty()) return run_with_plan(*a, *sub, ctx);
        RunConfig rc = run_config_of(*a, *sub);
        a->rw.live = sub->count("--live") > 0;
        a->rw.keep_domain = sub->count("--domain") > 0 || sub->count("--scenario") > 0;
        if (!a->rw.empty()) rc = apply_run_rewrites(rc, a->rw, ctx.registry);
        LaunchOptions lo;
        lo.layout = a->layout;
        lo.log_level = ctx.log_level;
        return launch_run(std::move(rc), ctx.registry, lo);
    };
    return sub;
}

CLI::App* add_component_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    struct Args {
        std::string names, config;
        bool free_running{false};
        bool rejoin{false};
    };
    auto a = std::make_shared<Args>();
    auto* sub = app.add_subcommand("component", "run one or more components (comma-separated) in this process");
    sub->add_option("names", a->names, "component name(s) from the run config")->required();
    sub->add_option("--config", a->config, "run config (YAML)")->required();
    sub->add_flag("--free-running", a->free_running, "not in the lockstep barrier; inputs use the latest samples");
    sub->add_flag("--rejoin", a->rejoin, "come back into a running run after being declared dead (docs/faults.md)");
    run = [a, &ctx]() -> int {
        setup_logging(a->names, ctx.log_level);
        install_stop_signal_handlers();
        const RunConfig rc = RunConfig::load(a->config);
        auto members = rc.build(ctx.registry, split_topics(a->names));
        HostOptions ho;
        ho.free_running = a->free_running;
        ho.rejoin = a->rejoin;
        ho.rebuild = [&rc, &ctx](const std::string& name) { return rc.build_one(ctx.registry, name); };
        keep_participants_until_exit();  // leave without a DISPOSE (dds/process/process_exit.hpp)
        int code = kExitOk;
        {
            DdsHost host(rc, std::move(members), ho);
            code = host.run();
            // Every component has finished (its files are complete); only the DDS tear-down is left. The launcher
            // ends a member that outlives the clock by member_timeout_s + 3 s, so leave before that.
            bound_teardown(code, rc.member_timeout_s + kMemberTeardownMarginS);
        }  // every component destroyed
        exit_keeping_participants(code);
    };
    return sub;
}

CLI::App* add_clock_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    auto config = std::make_shared<std::string>();
    auto ready_fd = std::make_shared<int>(-1);
    auto* sub = app.add_subcommand("clock", "run the lockstep clock of a run");
    sub->add_option("--config", *config, "run config (YAML)")->required();
    sub->add_option("--ready-fd", *ready_fd, "write \"1\" to this file descriptor once the domain is the run's "
                                             "(the launcher starts the members then)")
        ->check(CLI::Range(3, 1023));
    run = [config, ready_fd, &ctx]() -> int {
        setup_logging(kClockName, ctx.log_level);
        install_stop_signal_handlers();
        const RunConfig rc = RunConfig::load(*config);
        keep_participants_until_exit();  // leave without a DISPOSE (dds/process/process_exit.hpp)
        int code = kExitOk;
        {
            ClockOptions co;
            co.ready_fd = *ready_fd;
            Clock clock(rc, co);
            code = clock.run();
            bound_teardown(code, kClockTeardownDeadlineS);
        }  // clock_summary.yaml and faults.yaml are written
        exit_keeping_participants(code);
    };
    return sub;
}

std::string validate_scenario(const std::string& scenario, const ComponentRegistry& reg) {
    const RunConfig rc = RunConfig::load(resolve_scenario(scenario));
    auto comps = rc.build(reg);
    std::vector<Component*> raw;
    for (auto& c : comps) raw.push_back(c.get());
    const Graph g = build_graph(raw);
    std::string order;
    for (auto* c : g.order) order += (order.empty() ? "" : " -> ") + c->name();
    return rc.origin + ": valid; " + std::to_string(comps.size()) + " components, " + std::to_string(rc.info.steps) +
           " steps; step order: " + order;
}

CLI::App* add_validate_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    auto scenario = std::make_shared<std::string>();
    auto* sub = app.add_subcommand("validate", "validate a scenario / run config without running it");
    sub->add_option("--scenario", *scenario, "scenario name or YAML file")->required();
    run = [scenario, &ctx]() {
        setup_logging("gdnav", ctx.log_level);
        spdlog::info("{}", validate_scenario(*scenario, ctx.registry));
        return 0;
    };
    return sub;
}

// The topic graph of a scenario's components (framework/graph.hpp, graph_dot), as DOT text or, through Graphviz's
// `dot`, as SVG.
int print_topic_graph(const std::string& format, const std::string& scenario, const ComponentRegistry& reg) {
    const RunConfig rc = RunConfig::load(resolve_scenario(scenario::scenario_alias(scenario)));
    const auto comps = rc.build(reg);
    std::vector<Component*> raw;
    for (const auto& c : comps) raw.push_back(c.get());
    const std::string dot = graph_dot(raw, "gdnav topics, scenario " + scenario + " (dashed: the previous step's)");
    if (format == "dot") {
        std::fputs(dot.c_str(), stdout);
        return 0;
    }
    if (std::system("command -v dot > /dev/null 2>&1") != 0)
        throw std::runtime_error("gdnav list --graph svg needs Graphviz's `dot` (apt-get install graphviz); "
                                 "--graph dot prints the text");
    std::fflush(stdout);
    FILE* p = popen("dot -Tsvg", "w");
    if (p == nullptr) throw std::runtime_error("gdnav list --graph svg: cannot start `dot`");
    std::fputs(dot.c_str(), p);
    if (pclose(p) != 0) throw std::runtime_error("gdnav list --graph svg: `dot` failed");
    return 0;
}

CLI::App* add_list_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    auto* sub = app.add_subcommand("list", "list component types, topics and scenarios, or draw the topic graph");
    auto graph = std::make_shared<std::string>();
    auto graph_scenario = std::make_shared<std::string>("default");
    sub->add_option("--graph", *graph, "print the topic graph of --scenario instead: dot (Graphviz text) | svg")
        ->check(CLI::IsMember({"dot", "svg"}));
    sub->add_option("--scenario", *graph_scenario, "scenario of --graph (default: default)");
    run = [&ctx, graph, graph_scenario]() {
        if (!graph->empty()) return print_topic_graph(*graph, *graph_scenario, ctx.registry);
        std::printf("component types:\n");
        for (const auto& t : ctx.registry.types()) std::printf("  %-22s %s\n", t.c_str(), ctx.registry.description(t).c_str());
        std::printf("topics:\n");
        for (const auto& t : known_topics()) std::printf("  %s\n", t.c_str());
        std::printf("scenarios (%s):\n", (config_dir() / "scenarios").c_str());
        std::error_code ec;
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(config_dir() / "scenarios", ec))
            if (e.path().extension() == ".yaml") names.push_back(e.path().stem().string());
        std::sort(names.begin(), names.end());
        for (const auto& n : names) std::printf("  %s\n", n.c_str());
        return 0;
    };
    return sub;
}

CLI::App* add_bench_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    auto a = std::make_shared<bench::BenchOptions>();
    auto* sub = app.add_subcommand("bench", "measure steps/s and real-time factor per layout, and model costs");
    sub->add_option("--scenario", a->scenario, "scenario name or YAML file");
    sub->add_option("--steps", a->steps, "steps per measurement");
    sub->add_option("--layouts", a->layouts, "layouts to measure")->delimiter(',');
    sub->add_option("--mc-runs", a->mc_runs, "runs of scenarios #1 and #2 for the Monte Carlo throughput (0: skip)");
    sub->add_option("--mc-steps", a->mc_steps, "steps of each of those runs (default: full length)");
    sub->add_option("--mc-jobs", a->mc_jobs, "runs in parallel in that measurement")->check(CLI::Range(1, 256));
    sub->add_option("--json", a->json, "also write the figures to this JSON file");
    sub->add_option("--security", a->security,
                    "DDS Security directory (gdnav pki init): also measure the composed layout with security on");
    run = [a, &ctx]() {
        setup_logging("gdnav", ctx.log_level);
        a->log_level = ctx.log_level;
        const bench::BenchFigures fig = bench::measure_bench(*a, ctx.registry);
        std::fputs(bench::bench_tables(fig, *a).c_str(), stdout);
        if (!a->json.empty()) bench::write_bench_json(fig, a->json);
        return 0;
    };
    return sub;
}

}  // namespace gdnav::cli
