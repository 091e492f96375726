#pragma once
// Quaternion helpers for filters that carry q_nb as a raw 4-vector (w, x, y, z) in an additive EKF state.
// Convention (common/core/math/rotation.hpp): Hamilton, scalar first, q_nb rotates body components into NED:
//   forward  v_n = q (x) [0, v_b] (x) q*  = R(q) v_b
//   backward v_b = q* (x) [0, v_n] (x) q  = R(q)^T v_n
// Here R(q) is the homogeneous quadratic form of q (equal to the rotation matrix when |q| = 1 and scaled by |q|^2
// otherwise), so that the Jacobians below are exact derivatives for any 4-vector, which is what numerical
// differentiation of an additive EKF observation sees.
//   d_rot_dq(q, v)      = d(R(q) v)/dq            (3x4)
//   d_rot_t_dq(q, v)    = d(R(q)^T v)/dq          (3x4)
//   omega_right(w)      = Omega_R(w): q (x) [0, w] = Omega_R(w) q           (4x4)
//   xi(q)               = Xi(q):      q (x) [0, w] = Xi(q) w                 (4x3)
//   quat_kinematics(q, w) = 0.5 q (x) [0, w]; its Jacobians are 0.5 Omega_R(w) (wrt q) and 0.5 Xi(q) (wrt w).
//   att_error_jacobian(q) = G with 2 vec(dq (x) q*) = G dq: maps a quaternion perturbation to the small rotation
//                           angle about N axes (error applied on the NED side, q_true = dtheta_n (x) q_est).
#include <Eigen/Core>

namespace gdnav::core::filters {

using Quat4 = Eigen::Vector4d;  // (w, x, y, z)
using Mat34 = Eigen::Matrix<double, 3, 4>;
using Mat43 = Eigen::Matrix<double, 4, 3>;

Eigen::Matrix3d rot_quadratic(const Quat4& q);
Eigen::Vector3d rotate(const Quat4& q, const Eigen::Vector3d& v_b);       // R(q) v
Eigen::Vector3d rotate_back(const Quat4& q, const Eigen::Vector3d& v_n);  // R(q)^T v

Mat34 d_rot_dq(const Quat4& q, const Eigen::Vector3d& v);
Mat34 d_rot_t_dq(const Quat4& q, const Eigen::Vector3d& v);

Eigen::Matrix4d omega_right(const Eigen::Vector3d& w);
Mat43 xi(const Quat4& q);
Quat4 quat_kinematics(const Quat4& q, const Eigen::Vector3d& w);

Mat34 att_error_jacobian(const Quat4& q_est);

}  // namespace gdnav::core::filters
namespace gdnav { namespace filters = core::filters; }  // the short name (docs/architecture.md, "Namespaces")
