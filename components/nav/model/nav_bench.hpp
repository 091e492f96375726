#pragma once
// Per-step cost of each navigation filter on synthetic data (nav_synthetic.hpp, a gentle constant-rate turn).
// Measures process CPU time (std::clock), so it lives outside the model library; the lead can call it from
// `gdnav bench`. Each filter is timed in its own loop over precomputed inputs. Numbers are for information only
// (no test asserts on them).
#include <cstdint>

#include "config/config.hpp"

namespace gdnav::nav {

struct NavBenchResult {
    int steps{0};
    double air_us_per_step{0.0};
    double att_us_per_step{0.0};
    double pos_aided_us_per_step{0.0};   // GNSS-aided 12-state EKF (fix every 100 steps)
    double pos_denied_us_per_step{0.0};  // GNSS-denied 6-state EKF + reconstruction
};

// tuning: the whole config/nav/tuning.yaml; variant: a whole variant file (e.g. config/nav/variants/baseline.yaml).
NavBenchResult bench_nav_filters(const config::Config& tuning, const config::Config& variant, int steps,
                                 std::uint64_t seed = 1);

}  // namespace gdnav::nav
