#pragma once
// A gdnav montecarlo batch run for a test (direct layout, two jobs, no report) and the per-run figures the navigation
// batch tests judge: the mean attitude error ‖Δr̂‖ over the paper's window, the final horizontal error, the aligned
// flag, and the run's files removed after reading. Runs are bit-reproducible, so the figures are the same on every
// machine.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "process_util.hpp"

namespace gdnav::testing {

struct BatchFigures {
    std::vector<double> att_deg, hor_m;
    std::vector<bool> aligned;
    double att_mean{0.0}, hor_mean{0.0};
};

inline BatchFigures run_nav_batch(const std::string& tag, const std::string& scenario, int runs,
                                  const std::vector<std::string>& extra) {
    constexpr double kDeg = 180.0 / 3.14159265358979323846;
    const std::filesystem::path dir = temp_dir(tag);
    std::vector<std::string> args = {GDNAV_GDNAV_EXE, "montecarlo", "--scenario", scenario, "--runs",
                                     std::to_string(runs), "--jobs", "2", "--layout", "direct", "--seed", "1",
                                     "--no-figures", "--no-report", "--out", dir.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const Result r = run(args, 900.0);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    BatchFigures b;
    for (int i = 0; i < runs; ++i) {
        char name[32];
        std::snprintf(name, sizeof(name), "run_%04d", i);
        const YAML::Node m = YAML::LoadFile((dir / "runs" / name / "metrics.yaml").string());
        EXPECT_TRUE(m["complete"].as<bool>()) << i;
        b.att_deg.push_back(m["signals"]["rot_rad"]["mean"].as<double>() * kDeg);
        b.hor_m.push_back(std::fabs(m["signals"]["hor_m"]["final"].as<double>()));
        b.aligned.push_back(m["alignment"] && m["alignment"]["aligned"].as<bool>());
        b.att_mean += b.att_deg.back() / runs;
        b.hor_mean += b.hor_m.back() / runs;
    }
    std::filesystem::remove_all(dir);
    return b;
}

// Prints the two batches run by run and their means, and checks (EXPECT) that every run of `cand` aligned and none
// diverged (mean attitude error under 1 deg).
inline void print_and_check_runs(const BatchFigures& base, const BatchFigures& cand, const std::string& cand_name) {
    std::printf("run  attitude mean [deg]: aligned  %s | final horizontal [m]: aligned  %s\n", cand_name.c_str(),
                cand_name.c_str());
    for (std::size_t i = 0; i < cand.att_deg.size(); ++i) {
        std::printf("%3zu  %28.3f %10.3f | %28.1f %10.1f\n", i, base.att_deg[i], cand.att_deg[i], base.hor_m[i],
                    cand.hor_m[i]);
        EXPECT_TRUE(cand.aligned[i]) << "run " << i << " never aligned";
        EXPECT_LT(cand.att_deg[i], 1.0) << "run " << i << " diverged";
    }
    std::printf("mean %27.3f %10.3f | %28.1f %10.1f  (ratios %.3f, %.3f)\n", base.att_mean, cand.att_mean,
                base.hor_mean, cand.hor_mean, cand.att_mean / base.att_mean, cand.hor_mean / base.hor_mean);
}

// The calibrated scenarios' aligned start: the paper's filters from the sensors' published pre-flight alignment on
// the same runs (config/scenarios/paper2_calibrated.yaml).
inline const std::vector<std::string> kAlignedStart = {
    "--set", "components.nav_att.init_mode=alignment", "--set", "components.nav_pos.init_mode=alignment",
    "--set", "components.nav_att.in_flight_alignment=~", "--set", "components.nav_pos.follow_in_flight_alignment=false"};

}  // namespace gdnav::testing
