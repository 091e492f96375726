#include "metrics/run_metrics.hpp"

#include <cmath>
#include <limits>

namespace gdnav::core::metrics {

double signal_value(const NavErrors& e, Signal s) {
    switch (s) {
        case Signal::yaw: return e.yaw_rad;
        case Signal::pitch: return e.pitch_rad;
        case Signal::bank: return e.bank_rad;
        case Signal::rot: return e.rot_rad;
        case Signal::tas: return e.tas_mps;
        case Signal::aoa: return e.aoa_rad;
        case Signal::aos: return e.aos_rad;
        case Signal::dT: return e.dT_K;
        case Signal::h: return e.h_m;
        case Signal::vn: return e.v_n_mps.x();
        case Signal::ve: return e.v_n_mps.y();
        case Signal::hor: return e.hor_m;
        case Signal::cross: return e.cross_m;
        case Signal::along: return e.along_m;
    }
    return 0.0;
}

void RunMetrics::add_ground_speed(double t_s, double dt_s, double v_mps) {
    // Intervals [t_prev, t] that start at or after t_GNSS (tolerance: half a step, so t_GNSS on the grid counts).
    if (have_prev_ && prev_t_s_ >= t_gnss_s_ - 0.5 * dt_s) distance_m_ += 0.5 * (prev_speed_mps_ + v_mps) * (t_s - prev_t_s_);
    prev_t_s_ = t_s;
    prev_speed_mps_ = v_mps;
    have_prev_ = true;
}

void RunMetrics::note_estimates(double t_s, double dt_s, const std::array<bool, kEstimateCount>& present) {
    if (t_s < t_start_s_ - 0.5 * dt_s) return;
    t_last_noted_s_ = t_s;
    for (std::size_t i = 0; i < kEstimateCount; ++i)
        if (present[i]) last_estimate_s_[i] = t_s;
}

bool RunMetrics::estimate_stopped(Estimate e) const {
    // Nothing noted: nothing is claimed.
    return !std::isnan(t_last_noted_s_) && !(last_estimate_s(e) == t_last_noted_s_);
}

bool RunMetrics::estimates_complete() const {
    for (std::size_t i = 0; i < kEstimateCount; ++i)
        if (estimate_stopped(static_cast<Estimate>(i))) return false;
    return true;
}

void RunMetrics::add_errors(double t_s, double dt_s, const NavErrors& e) {
    if (t_s < t_start_s_ - 0.5 * dt_s) return;
    distance_at_last_m_ = distance_m_;
    for (const auto& info : kSignals) stats_[index(info.signal)].add(signal_value(e, info.signal));
    if (t_s >= t_att_trend_s_ - 0.5 * dt_s) att_trend_.add(t_s, e.rot_rad);
    if (t_s >= t_gnss_s_ - 0.5 * dt_s) hor_trend_.add(t_s, e.hor_m);
    t_last_s_ = t_s;
}

double RunMetrics::final_percent(Signal s) const {
    // Equal when every estimate reached the last step; otherwise the final error is that of t_last.
    const double d = estimates_complete() ? distance_m_ : distance_at_last_m_;
    if (!(d > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    return 100.0 * stats(s).last() / d;
}

}  // namespace gdnav::core::metrics
