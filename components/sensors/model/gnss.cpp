#include "sensors/model/gnss.hpp"

#include <cmath>
#include <stdexcept>

#include <GeographicLib/LocalCartesian.hpp>

namespace gdnav::sensors {

void GnssReceiver::configure(const GnssParams& params, rnd::Stream group_stream) {
    params_ = params;
    const GnssGrade& g = params.grade;
    steps_per_fix_ = static_cast<std::uint64_t>(std::llround(g.fix_period_s / params.dt_s));
    if (steps_per_fix_ == 0) throw std::invalid_argument("GnssReceiver: fix period shorter than the sensor step");
    last_fix_step_.reset();
    has_fixes_ = true;
    if (params.loss_time_s) {
        const double x = (*params.loss_time_s - params.t0_s) / params.dt_s;
        if (x < -1.0e-6) {
            has_fixes_ = false;
            last_fix_step_ = 0;
        } else {
            last_fix_step_ = static_cast<std::uint64_t>(std::floor(x + 1.0e-6));
        }
    }
    const rnd::Stream s = group_stream.child("gnss");
    vel_ = s.child("vel");
    pos_ = s.child("pos");
    iono_ = s.child("iono");
    const Vec3 w0 = g.iono_initial_steps * iono_.normal3();
    const Vec3 nu = iono_.normal3();
    for (int i = 0; i < 3; ++i) {
        walk_[i] = BandedRandomWalk(g.iono_band_steps, /*hard=*/false, w0[i]);
        node_prev_[i] = w0[i];
        node_next_[i] = walk_[i].step(nu[i]);
    }
    block_ = 0;
    last_ = GnssMeasurement{};
}

bool GnssReceiver::is_fix_epoch(std::uint64_t k) const {
    if (!has_fixes_ || k % steps_per_fix_ != 0) return false;
    return !last_fix_step_ || k <= *last_fix_step_;
}

Vec3 GnssReceiver::iono_error_m(std::uint64_t fix_index) {
    const auto u = static_cast<std::uint64_t>(params_.grade.iono_update_fixes);
    const std::uint64_t b = fix_index / u;
    if (b < block_) throw std::invalid_argument("GnssReceiver: step index went backwards");
    while (block_ < b) {
        node_prev_ = node_next_;
        const Vec3 nu = iono_.normal3();
        for (int i = 0; i < 3; ++i) node_next_[i] = walk_[i].step(nu[i]);
        ++block_;
    }
    const double frac = static_cast<double>(fix_index % u) / static_cast<double>(u);
    return params_.grade.iono_step_m * (node_prev_ + frac * (node_next_ - node_prev_));
}

GnssMeasurement GnssReceiver::measure(std::uint64_t k, double t_s, const GnssTruth& truth) {
    if (!is_fix_epoch(k)) {
        GnssMeasurement held = last_;
        held.step = k;
        held.t_s = t_s;
        held.fix_valid = false;
        return held;
    }
    const GnssGrade& g = params_.grade;
    GnssMeasurement out;
    out.step = k;
    out.t_s = t_s;
    out.fix_valid = true;
    out.v_n_mps = truth.v_n_mps + g.velocity_mps * vel_.normal3();
    const Vec3 nu = pos_.normal3();
    out.iono_err_n_m = iono_error_m(k / steps_per_fix_);
    out.pos_err_n_m = Vec3(g.horizontal_m * nu[0], g.horizontal_m * nu[1], g.vertical_m * nu[2]) + out.iono_err_n_m;
    // East-North-Up local frame at the true position.
    const GeographicLib::LocalCartesian enu(math::rad2deg(truth.lat_rad), math::rad2deg(truth.lon_rad), truth.h_m);
    double lat_deg = 0.0, lon_deg = 0.0, h_m = 0.0;
    enu.Reverse(out.pos_err_n_m[1], out.pos_err_n_m[0], -out.pos_err_n_m[2], lat_deg, lon_deg, h_m);
    out.lat_rad = math::deg2rad(lat_deg);
    // Keep the truth's longitude branch (e.g. 270 deg stays near 270 deg, not -90 deg).
    out.lon_rad = truth.lon_rad + math::wrap_pi(math::deg2rad(lon_deg) - truth.lon_rad);
    out.h_m = h_m;
    last_ = out;
    return out;
}

}  // namespace gdnav::sensors
