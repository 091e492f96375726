#include "metrics/run_metrics.hpp"

#include <limits>

namespace gdnav::metrics {

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

void RunMetrics::add_errors(double t_s, double dt_s, const NavErrors& e) {
    if (t_s < t_start_s_ - 0.5 * dt_s) return;
    for (const auto& info : kSignals) stats_[index(info.signal)].add(signal_value(e, info.signal));
    if (t_s >= t_att_trend_s_ - 0.5 * dt_s) att_trend_.add(t_s, e.rot_rad);
    if (t_s >= t_gnss_s_ - 0.5 * dt_s) hor_trend_.add(t_s, e.hor_m);
    t_last_s_ = t_s;
}

double RunMetrics::final_percent(Signal s) const {
    if (!(distance_m_ > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    return 100.0 * stats(s).last() / distance_m_;
}

}  // namespace gdnav::metrics
