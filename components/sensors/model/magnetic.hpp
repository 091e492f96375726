#pragma once
// Magnetometer triad (docs/sensors.md, "Magnetometers"; paper, "Sensors"): no bias drift, not on the IMU
// platform (no mounting rotation).
//
//   b~_b = (I + M_m) b_b + B_hi + B_off + (sigma_v / sqrt(dt)) nu_k,    b_b = R(q_nb)^T b_n (true field)
//   per run: B_hi = hard_iron N(0, I3), B_off = B0 N(0, I3), M_m full 3x3 (diagonal s N(0,1), off-diagonal m N(0,1),
//            scale factor, cross coupling and soft iron together)
//   E_mag = B_hi + B_off + M_m b_b (full error without white noise, in the output)
//
// Inputs: MagTruth (q_nb, TRUE b_n). Outputs: MagMeasurement. Streams: children "hard_iron", "offset", "scale",
// "noise" of the group stream's child "mag".
#include <cstdint>

#include "random/stream.hpp"
#include "sensors/model/sensor_io.hpp"
#include "sensors/model/suite.hpp"

namespace gdnav::sensors {

class Magnetometers {
public:
    void configure(const MagParams& params, rnd::Stream stream);
    MagMeasurement measure(std::uint64_t k, double t_s, const MagTruth& truth);

    [[nodiscard]] const MagParams& params() const { return params_; }
    [[nodiscard]] double noise_nT() const { return noise_sigma_; }  // per-sample sigma_v / sqrt(dt)
    [[nodiscard]] const Vec3& hard_iron_nT() const { return hard_iron_; }
    [[nodiscard]] const Vec3& offset_nT() const { return offset_; }
    [[nodiscard]] const Mat3& scale_cross() const { return m_; }

private:
    MagParams params_;
    Vec3 hard_iron_{Vec3::Zero()};
    Vec3 offset_{Vec3::Zero()};
    Mat3 m_{Mat3::Zero()};
    double noise_sigma_{0.0};
    rnd::Stream noise_;
};

}  // namespace gdnav::sensors
