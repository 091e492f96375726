#include "sensors/model/triad.hpp"

#include <cmath>

namespace gdnav::sensors {

void InertialTriad::configure(const TriadGrade& g, double band_steps, double dt_s, Coupling coupling,
                              rnd::Stream stream) {
    rnd::Stream offset = stream.child("offset");
    rnd::Stream scale = stream.child("scale");
    drift_ = stream.child("drift");
    noise_ = stream.child("noise");

    offset_ = g.bias_offset * offset.normal3();
    // Row-major draw order: diagonal entries use s, off-diagonal ones m. The lower-triangular triad still
    // draws (and discards) the upper entries so both couplings consume the same draws per entry.
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const double nu = scale.normal();
            if (i == j) {
                m_(i, j) = g.scale_factor * nu;
            } else if (coupling == Coupling::kFull || j < i) {
                m_(i, j) = g.cross_coupling * nu;
            } else {
                m_(i, j) = 0.0;
            }
        }
    }
    band_ = band_steps;
    for (auto& w : walk_) w = BandedRandomWalk(band_steps, /*hard=*/true, 0.0);
    drift_step_ = g.bias_drift * std::sqrt(dt_s);
    noise_sigma_ = g.system_noise / std::sqrt(dt_s);
}

math::Vec3 InertialTriad::sample_bias() {
    const math::Vec3 bias = offset_ + drift();
    const math::Vec3 nu = drift_.normal3();
    for (int i = 0; i < 3; ++i) walk_[i].step(nu[i]);
    return bias;
}

math::Vec3 InertialTriad::drift() const {
    return drift_step_ * math::Vec3(walk_[0].value(), walk_[1].value(), walk_[2].value());
}

}  // namespace gdnav::sensors
