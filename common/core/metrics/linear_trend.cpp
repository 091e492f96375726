#include "metrics/linear_trend.hpp"

#include <limits>

namespace gdnav::core::metrics {

namespace {
constexpr double kNoTrend = std::numeric_limits<double>::quiet_NaN();  // fewer than two distinct times
}

void LinearTrend::add(double t, double y) {
    ++n_;
    const double n = static_cast<double>(n_);
    const double dt = t - t_mean_;
    const double dy = y - y_mean_;
    t_mean_ += dt / n;
    y_mean_ += dy / n;
    // Co-moment updates: S_ab += (a - a_mean_old)(b - b_mean_new).
    s_tt_ += dt * (t - t_mean_);
    s_yy_ += dy * (y - y_mean_);
    s_ty_ += dt * (y - y_mean_);
}

double LinearTrend::slope() const { return n_ >= 2 && s_tt_ > 0.0 ? s_ty_ / s_tt_ : kNoTrend; }

double LinearTrend::r2() const {
    return n_ >= 2 && s_tt_ > 0.0 && s_yy_ > 0.0 ? s_ty_ * s_ty_ / (s_tt_ * s_yy_) : kNoTrend;
}

}  // namespace gdnav::core::metrics
