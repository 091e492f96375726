#pragma once
// Shared helpers of the sensor model tests.
#include <cmath>
#include <filesystem>
#include <vector>

#include "sensors/model/suite.hpp"

namespace gdnav::sensors::test {

inline std::filesystem::path sensors_config_dir() { return std::filesystem::path(GDNAV_SOURCE_DIR) / "config/sensors"; }

inline SensorSuiteParams baseline_suite() { return load_sensor_suite(sensors_config_dir() / "suite.yaml"); }

// Root mean square about zero: the estimator of sigma for zero-mean draws. Its relative standard error is
// 1 / sqrt(2 n) for n independent normal samples.
inline double rms(const std::vector<double>& x) {
    double s = 0.0;
    for (const double v : x) s += v * v;
    return std::sqrt(s / static_cast<double>(x.size()));
}

inline double mean(const std::vector<double>& x) {
    double s = 0.0;
    for (const double v : x) s += v;
    return s / static_cast<double>(x.size());
}

// Sample standard deviation about the sample mean (relative standard error ~ 1 / sqrt(2 (n - 1))).
inline double stddev(const std::vector<double>& x) {
    const double m = mean(x);
    double s = 0.0;
    for (const double v : x) s += (v - m) * (v - m);
    return std::sqrt(s / static_cast<double>(x.size() - 1));
}

}  // namespace gdnav::sensors::test
