#include "bench.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

#include "runtime/direct_executor.hpp"
#include "runtime/launcher.hpp"
#include "runtime/run_config.hpp"

namespace gdnav::app {

using namespace gdnav::runtime;

int run_bench(const BenchArgs& a, const ComponentRegistry& reg) {
    const auto base = std::filesystem::temp_directory_path() / ("gdnav-bench-" + std::to_string(getpid()));
    struct Row {
        std::string layout;
        double sps;
        double rt;
    };
    std::vector<Row> rows;
    double dt = 0.01;
    for (const auto& layout : a.layouts) {
        RunOverrides o;
        o.steps = a.steps;
        o.out_dir = (base / layout).string();
        RunConfig rc = RunConfig::load(resolve_scenario(a.scenario), o);
        dt = rc.info.dt_s;
        double sps = 0.0;
        if (layout == "direct") {
            std::filesystem::create_directories(rc.out_dir);
            run_direct(rc, reg, false, &sps);
        } else {
            LaunchOptions lo;
            lo.layout = layout;
            lo.log_level = "warn";
            if (launch_run(rc, reg, lo) != 0) {
                spdlog::error("bench: layout {} failed", layout);
                return 1;
            }
            const YAML::Node s = YAML::LoadFile((std::filesystem::path(rc.out_dir) / "clock_summary.yaml").string());
            sps = s["steps_per_s"].as<double>();
        }
        rows.push_back({layout, sps, sps * dt});
    }
    // Cost of each component's step, measured in the direct layout (no transport).
    std::vector<std::pair<std::string, double>> costs;
    {
        RunOverrides o;
        o.steps = a.steps;
        o.out_dir = (base / "profile").string();
        RunConfig rc = RunConfig::load(resolve_scenario(a.scenario), o);
        std::filesystem::create_directories(rc.out_dir);
        DirectExecutor ex(rc.build(reg), rc.info);
        ex.enable_profiling();
        ex.run();
        const auto us = ex.mean_step_us(rc.info.steps);
        for (std::size_t i = 0; i < us.size(); ++i) costs.emplace_back(ex.order()[i]->name(), us[i]);
    }
    std::filesystem::remove_all(base);
    std::printf("\nscenario %s, %llu steps of %.3f s\n", a.scenario.c_str(), static_cast<unsigned long long>(a.steps), dt);
    std::printf("%-12s %14s %16s\n", "layout", "steps/s", "x real time");
    for (const auto& r : rows) std::printf("%-12s %14.0f %16.1f\n", r.layout.c_str(), r.sps, r.rt);
    std::printf("\n%-22s %14s\n", "component", "us per step");
    for (const auto& [n, us] : costs) std::printf("%-22s %14.2f\n", n.c_str(), us);
    return 0;
}

}  // namespace gdnav::app
