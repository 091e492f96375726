#pragma once
// Error state of one inertial triad (three gyroscopes or three accelerometers), docs/sensors.md "Inertial triads":
//   per run:    bias offset  B_off = B0 N(0, I3)
//               scale/cross-coupling matrix M: diagonal s N(0,1); off-diagonal m N(0,1) (full, gyroscopes) or
//               only below the diagonal (lower-triangular, accelerometers: that triad defines the platform axes)
//   per sample: bias drift   b_drift(k) = sigma_u sqrt(dt) S_k, S_k a hard band-limited random walk
//               (BandedRandomWalk, +-N steps, S_0 = 0 at the first sample), advanced after each sample
//               white noise  (sigma_v / sqrt(dt)) N(0, I3)
// Streams (children of the stream passed to configure): "offset", "scale" (per run), "drift", "noise" (per
// sample), so a grade change rescales the same draws and per-run draws never shift per-sample ones.
#include "math/rotation.hpp"
#include "random/stream.hpp"
#include "sensors/model/banded_walk.hpp"
#include "sensors/model/grades.hpp"

namespace gdnav::sensors {

class InertialTriad {
public:
    enum class Coupling { kFull, kLowerTriangular };

    void configure(const TriadGrade& grade, double band_steps, double dt_s, Coupling coupling, rnd::Stream stream);

    // Returns the total bias of this sample, B_off + b_drift(k), then advances the drift to k + 1.
    math::Vec3 sample_bias();
    // One white-noise sample [U].
    math::Vec3 noise_sample() { return noise_sigma_ * noise_.normal3(); }

    [[nodiscard]] const math::Vec3& offset() const { return offset_; }
    [[nodiscard]] const math::Mat3& scale_cross() const { return m_; }
    [[nodiscard]] math::Vec3 drift() const;             // current b_drift [U]
    [[nodiscard]] double drift_step_sigma() const { return drift_step_; }  // sigma_u sqrt(dt)
    [[nodiscard]] double drift_band() const { return drift_step_ * band_; }  // N sigma_u sqrt(dt)
    [[nodiscard]] double noise_sigma() const { return noise_sigma_; }       // sigma_v / sqrt(dt)

private:
    math::Vec3 offset_{math::Vec3::Zero()};
    math::Mat3 m_{math::Mat3::Zero()};
    BandedRandomWalk walk_[3];
    double drift_step_{0.0};
    double noise_sigma_{0.0};
    double band_{0.0};
    rnd::Stream drift_;
    rnd::Stream noise_;
};

}  // namespace gdnav::sensors
