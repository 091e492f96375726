#include "metrics/running_stats.hpp"

#include <cmath>
#include <limits>

namespace gdnav::core::metrics {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

void RunningStats::add(double x) {
    ++n_;
    const double d = x - mean_;
    mean_ += d / static_cast<double>(n_);
    m2_ += d * (x - mean_);
    if (n_ == 1 || std::fabs(x) > std::fabs(smax_)) smax_ = x;
    last_ = x;
}

double RunningStats::mean() const { return n_ ? mean_ : kNaN; }
double RunningStats::std() const { return n_ ? std::sqrt(std::fmax(m2_, 0.0) / static_cast<double>(n_)) : kNaN; }
double RunningStats::smax() const { return n_ ? smax_ : kNaN; }
double RunningStats::last() const { return n_ ? last_ : kNaN; }

}  // namespace gdnav::core::metrics
