#include "launch/bench/bench.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <fmt/printf.h>
#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

#include "config/config.hpp"
#include "framework/direct_executor.hpp"
#include "framework/lockstep.hpp"
#include "framework/run_config.hpp"
#include "launch/batch/batch_runner.hpp"
#include "launch/launcher.hpp"

namespace gdnav::launch::bench {

using namespace gdnav::launch;
namespace fs = std::filesystem;

namespace {

// Steps/s of the scenario in one layout ("composed+security": composed with o.security).
double measure_layout(const BenchOptions& o, const framework::ComponentRegistry& reg, const std::string& name,
                      const fs::path& base, double& dt_s) {
    const bool secure = name == "composed+security";
    const std::string layout = secure ? "composed" : name;
    framework::RunOverrides ro;
    ro.steps = o.steps;
    ro.out_dir = (base / name).string();
    if (secure) ro.security = o.security;
    framework::RunConfig rc = framework::RunConfig::load(framework::resolve_scenario(o.scenario), ro);
    dt_s = rc.info.dt_s;
    double sps = 0.0;
    if (layout == "direct") {
        fs::create_directories(rc.out_dir);
        run_direct(rc, reg, false, &sps);
        return sps;
    }
    LaunchOptions lo;
    lo.layout = layout;
    lo.log_level = "warn";
    if (launch_run(rc, reg, lo) != 0) throw std::runtime_error("bench: layout " + name + " failed");
    const YAML::Node s = YAML::LoadFile((fs::path(rc.out_dir) / "clock_summary.yaml").string());
    return s["steps_per_s"].as<double>();
}

// Cost of each component's step, measured in the direct layout (no transport): the executor reads the steady clock
// around each component's step (two clock reads per component and step).
std::vector<std::pair<std::string, double>> measure_component_costs(const BenchOptions& o,
                                                                    const framework::ComponentRegistry& reg,
                                                                    const fs::path& base) {
    framework::RunOverrides ro;
    ro.steps = o.steps;
    ro.out_dir = (base / "profile").string();
    framework::RunConfig rc = framework::RunConfig::load(framework::resolve_scenario(o.scenario), ro);
    fs::create_directories(rc.out_dir);
    framework::DirectExecutor ex(rc.build(reg), rc.info);
    ex.enable_profiling();
    ex.run();
    const auto us = ex.mean_step_us(rc.info.steps);
    std::vector<std::pair<std::string, double>> out;
    for (std::size_t i = 0; i < us.size(); ++i) out.emplace_back(ex.order()[i]->name(), us[i]);
    return out;
}

// Runs per minute of full-length runs of paper scenario `scenario` in the direct layout: a batch of o.mc_runs runs
// (o.mc_steps steps each, or full length), o.mc_jobs at a time, timed without the report and extrapolated in
// proportion to the steps.
BenchMcFigure measure_montecarlo(const BenchOptions& o, const framework::ComponentRegistry& reg,
                                 const std::string& scenario, const fs::path& base) {
    BenchMcFigure f;
    f.scenario = scenario;
    f.runs = o.mc_runs;
    framework::RunOverrides ro;
    ro.out_dir = (base / ("mc_full_" + scenario)).string();
    f.steps_full = framework::RunConfig::load(framework::resolve_scenario("paper" + scenario), ro).info.steps;
    f.steps_run = o.mc_steps > 0 ? o.mc_steps : f.steps_full;
    batch::BatchSpec b;
    b.scenario = scenario;
    b.file = fs::absolute(framework::resolve_scenario("paper" + scenario));
    b.doc = YAML::Clone(config::Config::load(b.file).node());
    b.runs = o.mc_runs;
    b.jobs = o.mc_jobs;
    b.steps = o.mc_steps;
    b.seed_given = true;
    b.out = base / ("mc_" + scenario);
    b.log_level = o.log_level;
    const double t0 = framework::steady_now_s();
    if (batch::run_batch_shard(b, reg, batch::Shard{}) != 0) throw std::runtime_error("bench: the Monte Carlo batch failed");
    f.wall_s = framework::steady_now_s() - t0;
    f.runs_per_minute = 60.0 * static_cast<double>(f.runs) / f.wall_s * static_cast<double>(f.steps_run) /
                        static_cast<double>(f.steps_full);
    return f;
}

}  // namespace

BenchFigures measure_bench(const BenchOptions& o, const framework::ComponentRegistry& reg) {
    const auto base = fs::temp_directory_path() / ("gdnav-bench-" + std::to_string(getpid()));
    BenchFigures fig;
    fig.scenario = o.scenario;
    fig.steps = o.steps;
    fig.dt_s = 0.01;
    std::vector<std::string> layouts = o.layouts;
    if (!o.security.empty()) layouts.push_back("composed+security");
    for (const auto& name : layouts) {
        const double sps = measure_layout(o, reg, name, base, fig.dt_s);
        fig.layouts.push_back({name, sps, sps * fig.dt_s});
    }
    fig.component_us = measure_component_costs(o, reg, base);
    fig.mc_jobs = o.mc_jobs;
    if (o.mc_runs > 0)
        for (const char* scenario : {"1", "2"}) fig.montecarlo.push_back(measure_montecarlo(o, reg, scenario, base));
    fs::remove_all(base);
    return fig;
}

std::string bench_tables(const BenchFigures& fig, const BenchOptions& o) {
    std::string t = fmt::sprintf("\nscenario %s, %llu steps of %.3f s\n", o.scenario.c_str(),
                           static_cast<unsigned long long>(o.steps), fig.dt_s);
    t += fmt::sprintf("%-18s %14s %16s\n", "layout", "steps/s", "x real time");
    for (const auto& r : fig.layouts) t += fmt::sprintf("%-18s %14.0f %16.1f\n", r.layout.c_str(), r.steps_per_s, r.x_real_time);
    t += fmt::sprintf("\n%-22s %14s\n", "component", "us per step");
    for (const auto& [n, us] : fig.component_us) t += fmt::sprintf("%-22s %14.2f\n", n.c_str(), us);
    if (!fig.montecarlo.empty()) {
        t += fmt::sprintf("\nMonte Carlo, direct layout, %u jobs (extrapolated from %llu runs of %s steps each)\n",
                    fig.mc_jobs, static_cast<unsigned long long>(o.mc_runs),
                    o.mc_steps > 0 ? std::to_string(o.mc_steps) : "full-length");
        t += fmt::sprintf("%-10s %14s %18s\n", "scenario", "runs/min", "min per 100 runs");
        for (const auto& m : fig.montecarlo)
            t += fmt::sprintf("#%-9s %14.2f %18.2f\n", m.scenario.c_str(), m.runs_per_minute, 100.0 / m.runs_per_minute);
    }
    return t;
}

void write_bench_json(const BenchFigures& fig, const std::string& file) {
    std::ofstream f(file, std::ios::trunc);
    f << bench_json(fig, machine_info());
    if (!f) throw std::runtime_error("bench: cannot write " + file);
    spdlog::info("bench: figures written to {}", file);
}

}  // namespace gdnav::launch::bench
