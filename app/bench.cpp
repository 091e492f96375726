#include "bench.hpp"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

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
    std::filesystem::remove_all(base);
    std::printf("\nscenario %s, %llu steps of %.3f s\n", a.scenario.c_str(), static_cast<unsigned long long>(a.steps), dt);
    std::printf("%-12s %14s %16s\n", "layout", "steps/s", "x real time");
    for (const auto& r : rows) std::printf("%-12s %14.0f %16.1f\n", r.layout.c_str(), r.sps, r.rt);
    return 0;
}

}  // namespace gdnav::app
