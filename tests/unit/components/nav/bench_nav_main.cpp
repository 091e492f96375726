// bench_nav [steps] [tuning.yaml] [variant.yaml]: per-step cost of each navigation filter (information only).
#include <cstdlib>
#include <string>

#include <spdlog/spdlog.h>

#include "nav_bench.hpp"

int main(int argc, char** argv) {
    const int steps = argc > 1 ? std::atoi(argv[1]) : 20000;
    const std::string dir = std::string(GDNAV_SOURCE_DIR) + "/config/nav/";
    const std::string tuning = argc > 2 ? argv[2] : dir + "tuning.yaml";
    const std::string variant = argc > 3 ? argv[3] : dir + "variants/baseline.yaml";
    try {
        const auto r = gdnav::nav::bench_nav_filters(gdnav::config::Config::load(tuning),
                                                     gdnav::config::Config::load(variant), steps);
        spdlog::info("navigation filters, {} steps: air {:.2f} us/step, attitude {:.2f} us/step, "
                     "position GNSS-aided {:.2f} us/step, position GNSS-denied {:.2f} us/step",
                     r.steps, r.air_us_per_step, r.att_us_per_step, r.pos_aided_us_per_step,
                     r.pos_denied_us_per_step);
    } catch (const std::exception& e) {
        spdlog::error("{}", e.what());
        return 1;
    }
    return 0;
}
