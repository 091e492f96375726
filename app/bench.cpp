#include "bench.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

#include "bench_json.hpp"
#include "montecarlo.hpp"
#include "framework/direct_executor.hpp"
#include "launch/launcher.hpp"
#include "framework/lockstep.hpp"
#include "framework/run_config.hpp"

namespace gdnav::app {

using namespace gdnav::runtime;
namespace fs = std::filesystem;

namespace {

// Runs per minute of full-length runs of paper scenario `scenario` in the direct layout: a batch of a.mc_runs runs
// (a.mc_steps steps each, or full length), a.mc_jobs at a time, timed without the report and extrapolated in
// proportion to the steps.
BenchMcFigure measure_montecarlo(const BenchArgs& a, const CliContext& ctx, const std::string& scenario,
                                 const fs::path& base) {
    BenchMcFigure f;
    f.scenario = scenario;
    f.runs = a.mc_runs;
    RunOverrides o;
    o.out_dir = (base / ("mc_full_" + scenario)).string();
    f.steps_full = RunConfig::load(resolve_scenario("paper" + scenario), o).info.steps;
    f.steps_run = a.mc_steps > 0 ? a.mc_steps : f.steps_full;
    McArgs m;
    m.scenario = scenario;
    m.runs = a.mc_runs;
    m.jobs = a.mc_jobs;
    m.steps = a.mc_steps;
    m.seed_given = true;
    m.no_report = true;
    m.out = (base / ("mc_" + scenario)).string();
    const double t0 = steady_now_s();
    if (run_batch_shard(m, ctx, Shard{}) != 0) throw std::runtime_error("bench: the Monte Carlo batch failed");
    f.wall_s = steady_now_s() - t0;
    f.runs_per_minute = 60.0 * static_cast<double>(f.runs) / f.wall_s * static_cast<double>(f.steps_run) /
                        static_cast<double>(f.steps_full);
    return f;
}

}  // namespace

int run_bench(const BenchArgs& a, const CliContext& ctx) {
    const ComponentRegistry& reg = ctx.registry;
    const auto base = fs::temp_directory_path() / ("gdnav-bench-" + std::to_string(getpid()));
    BenchFigures fig;
    fig.scenario = a.scenario;
    fig.steps = a.steps;
    fig.dt_s = 0.01;
    std::vector<std::string> layouts = a.layouts;
    if (!a.security.empty()) layouts.push_back("composed+security");
    for (const auto& name : layouts) {
        const bool secure = name == "composed+security";
        const std::string layout = secure ? "composed" : name;
        RunOverrides o;
        o.steps = a.steps;
        o.out_dir = (base / name).string();
        if (secure) o.security = a.security;
        RunConfig rc = RunConfig::load(resolve_scenario(a.scenario), o);
        fig.dt_s = rc.info.dt_s;
        double sps = 0.0;
        if (layout == "direct") {
            fs::create_directories(rc.out_dir);
            run_direct(rc, reg, false, &sps);
        } else {
            LaunchOptions lo;
            lo.layout = layout;
            lo.log_level = "warn";
            if (launch_run(rc, reg, lo) != 0) {
                spdlog::error("bench: layout {} failed", name);
                return 1;
            }
            const YAML::Node s = YAML::LoadFile((fs::path(rc.out_dir) / "clock_summary.yaml").string());
            sps = s["steps_per_s"].as<double>();
        }
        fig.layouts.push_back({name, sps, sps * fig.dt_s});
    }
    // Cost of each component's step, measured in the direct layout (no transport): the executor reads the steady
    // clock around each component's step (two clock reads, ~40 ns, per component and step).
    {
        RunOverrides o;
        o.steps = a.steps;
        o.out_dir = (base / "profile").string();
        RunConfig rc = RunConfig::load(resolve_scenario(a.scenario), o);
        fs::create_directories(rc.out_dir);
        DirectExecutor ex(rc.build(reg), rc.info);
        ex.enable_profiling();
        ex.run();
        const auto us = ex.mean_step_us(rc.info.steps);
        for (std::size_t i = 0; i < us.size(); ++i) fig.component_us.emplace_back(ex.order()[i]->name(), us[i]);
    }
    fig.mc_jobs = a.mc_jobs;
    if (a.mc_runs > 0)
        for (const char* scenario : {"1", "2"}) fig.montecarlo.push_back(measure_montecarlo(a, ctx, scenario, base));
    fs::remove_all(base);

    std::printf("\nscenario %s, %llu steps of %.3f s\n", a.scenario.c_str(), static_cast<unsigned long long>(a.steps),
                fig.dt_s);
    std::printf("%-18s %14s %16s\n", "layout", "steps/s", "x real time");
    for (const auto& r : fig.layouts) std::printf("%-18s %14.0f %16.1f\n", r.layout.c_str(), r.steps_per_s, r.x_real_time);
    std::printf("\n%-22s %14s\n", "component", "us per step");
    for (const auto& [n, us] : fig.component_us) std::printf("%-22s %14.2f\n", n.c_str(), us);
    if (!fig.montecarlo.empty()) {
        std::printf("\nMonte Carlo, direct layout, %u jobs (extrapolated from %llu runs of %s steps each)\n", fig.mc_jobs,
                    static_cast<unsigned long long>(a.mc_runs),
                    a.mc_steps > 0 ? std::to_string(a.mc_steps).c_str() : "full-length");
        std::printf("%-10s %14s %18s\n", "scenario", "runs/min", "min per 100 runs");
        for (const auto& m : fig.montecarlo)
            std::printf("#%-9s %14.2f %18.2f\n", m.scenario.c_str(), m.runs_per_minute, 100.0 / m.runs_per_minute);
    }
    if (!a.json.empty()) {
        std::ofstream f(a.json, std::ios::trunc);
        f << bench_json(fig, machine_info());
        if (!f) throw std::runtime_error("bench: cannot write " + a.json);
        spdlog::info("bench: figures written to {}", a.json);
    }
    return 0;
}

}  // namespace gdnav::app
