#pragma once
// IMU platform (mounting) model, drawn once per run (docs/sensors.md, "IMU mounting").
//   T_RP,true = configured IMU position;  T_RP,est = T_RP,true + sigma_pos N(0, I3)
//   (yaw, pitch, bank)_BP,true ~ N(0, diag(sigma_mount)^2);  (.)_BP,est = (.)_BP,true + sigma_est N(0, I3)
//   R_BP = dcm_from_euler(euler_BP): platform -> body coordinates; R_PB = R_BP^T.
//   Lever arm from the CG B to the platform P in body axes: T_BP = T_RP - T_RB(m), where the CG T_RB moves
//   linearly with the fuel ratio r = (m_full - m) / (m_full - m_empty), r clamped to [0, 1].
#include "math/rotation.hpp"
#include "random/stream.hpp"
#include "sensors/model/suite.hpp"

namespace gdnav::sensors {

struct PlatformMounting {
    math::Euler euler_bp_true;                          // true body -> platform Euler angles
    math::Euler euler_bp_est;                           // calibrated (estimated) ones
    math::Mat3 r_bp_true{math::Mat3::Identity()};       // platform -> body, true
    math::Mat3 r_bp_est{math::Mat3::Identity()};        // platform -> body, as the IMU software assumes
    math::Vec3 t_rp_true_m{math::Vec3::Zero()};         // IMU position from the reference point, true
    math::Vec3 t_rp_est_m{math::Vec3::Zero()};          // IMU position as the IMU software assumes
};

// Draws the mounting of one run from `stream` (6 normals for the angles, 3 for the position, fixed order).
PlatformMounting draw_platform(const PlatformParams& p, rnd::Stream& stream);

// CG position T_RB [m] for the current mass.
math::Vec3 cg_position_m(const PlatformParams& p, double mass_kg);

}  // namespace gdnav::sensors
