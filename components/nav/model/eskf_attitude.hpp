#pragma once
// Error-state (multiplicative) formulation of the attitude filter (docs/navigation.md,
// "Error-state attitude filter"). Selected by `attitude.filter: error_state` in a variant file
// (config/nav/variants/att_error_state.yaml); AttitudeFilter calls these functions instead of its additive EKF.
//
// Nominal state: the 16 states of attitude_model.hpp (unit q_nb, w_nb_b, E_gyr, E_mag, B_dev_n), propagated with the
// same q_dot = 0.5 q (x) [0, w_nb] and observed with the same att::observe (so every specific-force variant works).
// Error state (15): dx = [dtheta_n (0..2), dw_nb (3..5), dE_gyr (6..8), dE_mag (9..11), dB_dev (12..14)] with the
// attitude error on the NED side, q_true = Exp(dtheta_n) (x) q_est; the others additive.
//   Error dynamics: dtheta_dot = R(q) dw_nb, all other errors constant  ->  Phi = I + A dt exactly (A^2 = 0),
//                   A nonzero only in the leading 6x6 block.
//   Observation Jacobians (R^T v after the error: R^T (I - [dtheta x]) v  ->  d/dtheta = R^T [v x]):
//     gyro  H_theta = R^T [(w_ie + w_en) x],           H_w = I, H_Egyr = I
//     accel H_theta = R^T [s x] + [w x] R^T [u x],      H_w = -[(R^T u) x]      (s = w_en x v - g + a_cor, u = the
//                                                                                variant's coupling velocity)
//     mag   H_theta = R^T [(B_model - B_dev) x],        H_Emag = I, H_Bdev = -R^T
//   Injection after the update: q <- Exp(dtheta) (x) q (unit by construction), others +=; covariance reset
//   P <- G P G^T with G = I except G_theta = I + 0.5 [dtheta x].
// Process noise per step: the additive tuning's quaternion-component variance q maps to 4 q rad^2 on each angle
// (|dq| = |dtheta|/2); the other Q entries are the additive filter's.
#include "attitude_model.hpp"

namespace gdnav::nav::eskf {

constexpr int kN = 15;
constexpr int kTh = 0, kW = 3, kEgyr = 6, kEmag = 9, kBdev = 12;
constexpr int kJ = 6;  // the error-state Jacobian is zero outside its leading 6x6 block
using ErrVec = filters::Vec<kN>;
using ErrCov = filters::SqMat<kN>;
using ErrJac = filters::Mat<att::kM, kN>;

// Leading 6x6 block of Phi = I + A dt at the nominal state x.
filters::SqMat<kJ> transition_leading(const att::StateVec& x, double dt_s);
// Error-state process noise (diagonal) from the additive filter's.
ErrVec process_noise(const att::StateVec& q_diag_additive);
// d y / d dx at the nominal state (rows as att::observe).
ErrJac observation_jacobian(const att::StateVec& x, const att::PnVector& pn, att::SpecificForceModel model);
// Applies the estimated error to the nominal state and resets the covariance (see above).
void inject(att::StateVec& x, ErrCov& p, const ErrVec& dx);
// Error-state covariance from the additive covariance at x (attitude block through att_error_jacobian), used to
// start from the same initial uncertainty as the additive filter.
ErrCov from_additive(const att::StateVec& x, const att::StateCov& p_additive);

}  // namespace gdnav::nav::eskf
