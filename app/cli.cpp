#include "cli.hpp"

#include <unistd.h>

#include <iostream>

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "bench.hpp"
#include "runtime/clock.hpp"
#include "runtime/dds_host.hpp"
#include "runtime/graph.hpp"
#include "runtime/launcher.hpp"
#include "runtime/lockstep.hpp"
#include "runtime/process_signals.hpp"
#include "runtime/topic_types.hpp"

namespace gdnav::app {

using namespace gdnav::runtime;

namespace {

void setup_logging(const std::string& who, const std::string& level) {
    auto logger = spdlog::stderr_color_mt(who);
    spdlog::set_default_logger(logger);
    spdlog::set_pattern("[%H:%M:%S.%e] [%n] %^%l%$: %v");
    spdlog::set_level(spdlog::level::from_str(level));
}

struct RunArgs {
    std::string scenario{"default"};
    std::uint64_t seed{1};
    std::uint64_t run_index{0};
    std::string layout{"distributed"};
    std::string out;
    double realtime{0.0};
    std::uint64_t steps{0};
    int domain{-1};
};

RunOverrides overrides_of(const RunArgs& a, CLI::App* sub) {
    RunOverrides o;
    if (sub->count("--seed")) o.seed = a.seed;
    if (sub->count("--run")) o.run_index = a.run_index;
    if (!a.out.empty()) o.out_dir = a.out;
    if (sub->count("--realtime")) o.realtime = a.realtime;
    if (a.steps > 0) o.steps = a.steps;
    if (a.domain >= 0) o.domain_id = a.domain;
    return o;
}

}  // namespace

int cli_main(int argc, char** argv, const ComponentRegistry& reg, const char* program_name) {
    register_gdnav_topics();
    CLI::App app{"gdnav — GNSS-denied fixed-wing UAV simulation and navigation", program_name};
    app.require_subcommand(1);
    app.fallthrough();  // global options (--log-level) may follow the subcommand
    std::string log_level = "info";
    app.add_option("--log-level", log_level, "trace, debug, info, warn, error")
        ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}));

    // gdnav run
    RunArgs ra;
    auto* run = app.add_subcommand("run", "run one simulation in a layout, supervising all its processes");
    run->add_option("--scenario", ra.scenario, "scenario name (config/scenarios/<name>.yaml) or YAML file");
    run->add_option("--seed", ra.seed, "master seed");
    run->add_option("--run", ra.run_index, "run index inside a batch");
    run->add_option("--layout", ra.layout, "direct | composed | distributed")
        ->check(CLI::IsMember({"direct", "composed", "distributed"}));
    run->add_option("--out", ra.out, "output directory");
    run->add_option("--realtime", ra.realtime, "pace to wall time x FACTOR (0 = as fast as possible)")
        ->check(CLI::Range(0.0, 1e6));
    run->add_option("--steps", ra.steps, "override the number of steps");
    run->add_option("--domain", ra.domain, "DDS domain id (default: derived from the process id)")
        ->check(CLI::Range(0, 232));

    // gdnav component
    std::string names, config_file;
    bool free_running = false;
    auto* comp = app.add_subcommand("component", "run one or more components (comma-separated) in this process");
    comp->add_option("names", names, "component name(s) from the run config")->required();
    comp->add_option("--config", config_file, "run config (YAML)")->required();
    comp->add_flag("--free-running", free_running, "not in the lockstep barrier; inputs use the latest samples");

    // gdnav clock
    std::string clock_config;
    auto* clk = app.add_subcommand("clock", "run the lockstep clock of a run");
    clk->add_option("--config", clock_config, "run config (YAML)")->required();

    // gdnav validate
    RunArgs va;
    auto* val = app.add_subcommand("validate", "validate a scenario / run config without running it");
    val->add_option("--scenario", va.scenario, "scenario name or YAML file")->required();

    // gdnav list
    auto* lst = app.add_subcommand("list", "list component types and topics");

    // gdnav bench
    BenchArgs ba;
    auto* bench = app.add_subcommand("bench", "measure steps/s and real-time factor per layout");
    bench->add_option("--scenario", ba.scenario, "scenario name or YAML file");
    bench->add_option("--steps", ba.steps, "steps per measurement");
    bench->add_option("--layouts", ba.layouts, "layouts to measure")->delimiter(',');

    CLI11_PARSE(app, argc, argv);

    try {
        if (*run) {
            setup_logging("gdnav", log_level);
            RunConfig rc = RunConfig::load(resolve_scenario(ra.scenario), overrides_of(ra, run));
            LaunchOptions lo;
            lo.layout = ra.layout;
            lo.log_level = log_level;
            return launch_run(std::move(rc), reg, lo);
        }
        if (*comp) {
            setup_logging(names, log_level);
            install_stop_signal_handlers();
            const RunConfig rc = RunConfig::load(config_file);
            auto members = rc.build(reg, split_topics(names));
            HostOptions ho;
            ho.free_running = free_running;
            DdsHost host(rc, std::move(members), ho);
            return host.run();
        }
        if (*clk) {
            setup_logging(kClockName, log_level);
            install_stop_signal_handlers();
            const RunConfig rc = RunConfig::load(clock_config);
            Clock clock(rc, ClockOptions{});
            return clock.run();
        }
        if (*val) {
            setup_logging("gdnav", log_level);
            const RunConfig rc = RunConfig::load(resolve_scenario(va.scenario));
            auto comps = rc.build(reg);
            std::vector<Component*> raw;
            for (auto& c : comps) raw.push_back(c.get());
            const Graph g = build_graph(raw);
            std::string order;
            for (auto* c : g.order) order += (order.empty() ? "" : " -> ") + c->name();
            spdlog::info("{}: valid; {} components, {} steps; step order: {}", rc.origin, comps.size(), rc.info.steps,
                         order);
            return 0;
        }
        if (*lst) {
            setup_logging("gdnav", log_level);
            for (const auto& t : reg.types()) spdlog::info("component type {:<22} {}", t, reg.description(t));
            for (const auto& t : known_topics()) spdlog::info("topic {}", t);
            return 0;
        }
        if (*bench) {
            setup_logging("gdnav", log_level);
            return run_bench(ba, reg);
        }
    } catch (const config::ConfigError& e) {
        spdlog::error("{}", e.what());
        return kExitConfig;
    } catch (const std::exception& e) {
        spdlog::error("{}", e.what());
        return 1;
    }
    return 0;
}

}  // namespace gdnav::app
