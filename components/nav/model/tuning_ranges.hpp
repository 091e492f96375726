#pragma once
// Allowed ranges of the navigation filters' tuning values (config/nav/tuning.yaml). The upper bounds are sanity
// limits (orders of magnitude above any tuning), not physics: they keep every variance, its square and sums of them
// finite. Units as in the key names.
#include <limits>

#include "config/config.hpp"

namespace gdnav::nav::tuning_ranges {

inline constexpr double kMaxVariance = 1.0e12;
inline constexpr double kMaxSigma = 1.0e6;
inline const config::Range kVariance{0.0, kMaxVariance};
inline const config::Range kPositiveVariance{std::numeric_limits<double>::min(), kMaxVariance};
inline const config::Range kPositiveSigma{std::numeric_limits<double>::min(), kMaxSigma};

}  // namespace gdnav::nav::tuning_ranges
