// Issue 5: each of the paper's six filter variants (and the baseline) is selected by config alone and runs end to
// end in the closed loop (paper scenario #2, direct layout), producing finite navigation metrics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "process_util.hpp"

using namespace gdnav::testing;

TEST(Variants, EveryVariantRunsEndToEndByConfigAlone) {
    const std::vector<std::string> variants{"baseline",
                                            "att_zero_fb_derivatives",
                                            "att_zero_fn_derivatives",
                                            "hor_double_integration",
                                            "hor_wind_integration",
                                            "ver_integration",
                                            "ver_airspeed_integration",
                                            "att_error_state",
                                            "eskf_mean_wind"};
    // Two runs at a time (the test has the machine to itself: RUN_SERIAL); each its own batch and domain.
    for (std::size_t first = 0; first < variants.size(); first += 2) {
        struct Started {
            std::string variant;
            std::filesystem::path out;
            pid_t pid;
        };
        std::vector<Started> started;
        for (std::size_t i = first; i < std::min(first + 2, variants.size()); ++i) {
            const std::string& v = variants[i];
            const auto out = temp_dir("variant-" + v);
            started.push_back({v, out, start({GDNAV_GDNAV_EXE, "montecarlo", "--scenario", "2", "--runs", "1", "--jobs",
                                           "1", "--layout", "direct", "--out", out.string(), "--variant", v},
                                          out.string() + ".log")});
        }
        for (const auto& [v, out, pid] : started) {
            SCOPED_TRACE(v);
            ASSERT_EQ(wait_for(pid, 300.0), 0) << read_file(out.string() + ".log");
            const YAML::Node m = YAML::LoadFile((out / "runs" / "run_0000" / "metrics.yaml").string());
            EXPECT_TRUE(m["complete"].as<bool>());
            const double att = m["signals"]["rot_rad"]["mean"].as<double>() * 180.0 / M_PI;
            const double hor = m["final_percent"]["hor"].as<double>();
            EXPECT_TRUE(std::isfinite(att) && std::isfinite(hor));
            // Sanity bounds far outside every variant's normal behaviour: a diverging filter breaks them.
            EXPECT_LT(att, 5.0);
            EXPECT_LT(hor, 50.0);
            std::printf("%-26s mean attitude error %.3f deg, final horizontal error %.2f %%\n", v.c_str(), att, hor);
        }
    }
}
