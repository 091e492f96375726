#pragma once
// Inertial measurement unit: gyroscope and accelerometer triads on a strapdown platform (docs/sensors.md,
// "Inertial triads" and "IMU mounting"; paper, "Sensors"). Called once per sensor step (dt = params.dt_s).
//
//   gyroscopes:     w~ = R^_BP (I + M_g) R_PB w_ib_b + b_g(k) + (sigma_v,g / sqrt(dt)) nu_k
//   accelerometers: f~ = R^_BP (I + M_a) R_PB (f_ib_b + l_true) - l_est + b_a(k) + (sigma_v,a / sqrt(dt)) nu_k
//       l_true = w x (w x T_BP,true) + dw x T_BP,true          true rate and angular acceleration (truth input)
//       l_est  = w~ x (w~ x T_BP,est) + dw~ x T_BP,est         what the IMU software compensates, from its own
//       dw~    = (w~_k - w~_{k-1}) / dt                         gyro output; dw~ = 0 at the first step or after a gap
//   b(k) = B_off + b_drift(k), M_g full, M_a lower-triangular (InertialTriad); R_BP, R^_BP, T_BP (PlatformMounting).
//   The output is the specific force at the CG and the inertial rate, in body axes as the platform estimates them.
//
// Deviation from the reference: its gyroscope model leaves the main term w unrotated (only the scale/cross term
// goes through R^_BP M_g R_PB), i.e. it ignores the residual mounting misalignment for the gyroscopes. Both triads
// sit on the same platform, so here both see R^_BP (I + M) R_PB (residual ~0.03 deg).
//
// Inputs:  InertialTruth (f_ib_b at the CG, w_ib_b, dw_ib_b, mass for the CG position).
// Outputs: ImuMeasurement (f_b, w_b, and the full errors E_acc, E_gyr without white noise).
// Random streams: children "gyr", "acc" (see InertialTriad) and "platform" of the group stream.
#include <cstdint>

#include "random/stream.hpp"
#include "sensors/model/platform.hpp"
#include "sensors/model/sensor_io.hpp"
#include "sensors/model/suite.hpp"
#include "sensors/model/triad.hpp"

namespace gdnav::sensors {

// Per-sample standard deviations the filters build their covariances from.
struct InertialNoise {
    double gyr_noise_rps{0.0};          // sigma_v,g / sqrt(dt)
    double gyr_drift_step_rps{0.0};     // sigma_u,g sqrt(dt)
    double gyr_drift_band_rps{0.0};     // N sigma_u,g sqrt(dt)
    double gyr_bias_offset_rps{0.0};    // B0,g
    double acc_noise_mps2{0.0};         // sigma_v,a / sqrt(dt)
    double acc_drift_step_mps2{0.0};    // sigma_u,a sqrt(dt)
    double acc_drift_band_mps2{0.0};    // N sigma_u,a sqrt(dt)
    double acc_bias_offset_mps2{0.0};   // B0,a
};

class InertialSensors {
public:
    // Draws the per-run quantities (offsets, scale/cross-coupling, mounting) from `stream`.
    void configure(const InertialParams& params, rnd::Stream stream);
    // One sample at step k (t_s is only copied to the output).
    ImuMeasurement measure(std::uint64_t k, double t_s, const InertialTruth& truth);

    [[nodiscard]] const InertialParams& params() const { return params_; }
    [[nodiscard]] InertialNoise noise() const;
    [[nodiscard]] const PlatformMounting& mounting() const { return mount_; }
    [[nodiscard]] const InertialTriad& gyr() const { return gyr_; }
    [[nodiscard]] const InertialTriad& acc() const { return acc_; }

private:
    InertialParams params_;
    PlatformMounting mount_;
    InertialTriad gyr_;
    InertialTriad acc_;
    math::Mat3 a_gyr_{math::Mat3::Identity()};  // R^_BP (I + M_g) R_PB
    math::Mat3 a_acc_{math::Mat3::Identity()};  // R^_BP (I + M_a) R_PB
    math::Vec3 w_prev_{math::Vec3::Zero()};     // previous measured rate
    std::uint64_t k_prev_{0};
    bool has_prev_{false};
};

}  // namespace gdnav::sensors
