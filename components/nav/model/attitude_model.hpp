#pragma once
// State, observation model and Jacobians of the attitude filter (paper "Attitude Filter"; docs/navigation.md
// "Attitude filter"). Kept apart from the filter class so the Jacobian tests can exercise them directly.
//
// State (16, additive, quaternion as a raw 4-vector):
//   x = [q_nb (0..3), w_nb_b (4..6), E_gyr (7..9), E_mag (10..12), B_dev_n (13..15)],  B_dev = B_model - B_true
// State equation: q_dot = 0.5 q (x) [0, w_nb];  all other states constant.
//   A_qq = 0.5 Omega_R(w_nb),  A_qw = 0.5 Xi(q).
// Observation (9) y = [w_ib_b (gyro), f_ib_b (accel), B_b (magnetometer)], with p_n from the previous step:
//   gyro:  w~ = w_nb + R^T (w_ie_n + w_en_n) + E_gyr
//   accel: f~ = c(x, p_n) + R^T (w_en_n x v_n - g_model_n + a_cor_n) + E_acc
//   mag:   B~ = R^T (B_model_n - B_dev_n) + E_mag
// The attitude variants differ ONLY in the coupling term c (SpecificForceModel):
//   baseline (paper):          c = w_nb x [R^T (v_n - wind_n)]  (airspeed & turbulence derivatives dropped in body,
//                                                                wind derivative dropped in NED)
//   zero_fb_derivatives:        c = w_nb x [R^T v_n]             (whole ground-velocity derivative dropped in body)
//   zero_fn_derivatives:        c = 0                            (whole ground-velocity derivative dropped in NED)
// R = R(q) is the quadratic form of filters/quat_jacobians.hpp (rotation matrix for unit q).
#include <optional>

#include <Eigen/Core>

#include "filters/ekf.hpp"
#include "nav_types.hpp"

namespace gdnav::nav::att {

constexpr int kN = 16;
constexpr int kM = 9;
using StateVec = filters::Vec<kN>;
using StateCov = filters::SqMat<kN>;
using MeasVec = filters::Vec<kM>;
using MeasJac = filters::Mat<kM, kN>;

// State indices.
constexpr int kQ = 0, kW = 4, kEgyr = 7, kEmag = 10, kBdev = 13;
// The state Jacobian is zero outside its leading kJ x kJ block.
constexpr int kJ = 7;
// Observation indices.
constexpr int kYgyr = 0, kYacc = 3, kYmag = 6;

enum class SpecificForceModel { kBaseline, kZeroBodyDerivatives, kZeroNedDerivatives };

// The p_n vector of the paper (eq. filter_att_obs_pvec): everything the observations take from the position filter.
struct PnVector {
    Vec3 g_model_n{Vec3::Zero()};
    Vec3 b_model_n{Vec3::Zero()};
    Vec3 v_n{Vec3::Zero()};
    Vec3 wind_n{Vec3::Zero()};
    Vec3 w_ie_n{Vec3::Zero()};
    Vec3 w_en_n{Vec3::Zero()};
    Vec3 a_cor_n{Vec3::Zero()};
    Vec3 acc_err_b{Vec3::Zero()};
};
// p_n = f(x_gdt, v_n, wind_n, E_acc) (paper eq. filter_att_obs_pvec_dependencies), from the previous position estimate.
PnVector make_pn(const PositionEstimate& pos);

// The one variant-specific piece: the NED velocity the body rate acts on in the specific-force observation,
// or nullopt when the coupling term is dropped.
std::optional<Vec3> coupling_velocity_n(SpecificForceModel model, const PnVector& pn);

StateVec derivative(const StateVec& x);
StateCov state_jacobian(const StateVec& x);
MeasVec observe(const StateVec& x, const PnVector& pn, SpecificForceModel model);
MeasJac observation_jacobian(const StateVec& x, const PnVector& pn, SpecificForceModel model);

}  // namespace gdnav::nav::att
