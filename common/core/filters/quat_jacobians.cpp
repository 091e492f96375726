#include "filters/quat_jacobians.hpp"

#include "math/rotation.hpp"

namespace gdnav::core::filters {

Eigen::Matrix3d rot_quadratic(const Quat4& q) {
    const double w = q(0), x = q(1), y = q(2), z = q(3);
    Eigen::Matrix3d r;
    r << w * w + x * x - y * y - z * z, 2.0 * (x * y - w * z), 2.0 * (x * z + w * y),  //
        2.0 * (x * y + w * z), w * w - x * x + y * y - z * z, 2.0 * (y * z - w * x),   //
        2.0 * (x * z - w * y), 2.0 * (y * z + w * x), w * w - x * x - y * y + z * z;
    return r;
}

Eigen::Vector3d rotate(const Quat4& q, const Eigen::Vector3d& v_b) { return rot_quadratic(q) * v_b; }

Eigen::Vector3d rotate_back(const Quat4& q, const Eigen::Vector3d& v_n) {
    return rot_quadratic(q).transpose() * v_n;
}

// d(q (x) v (x) q*)/dq = 2 [ w v + u x v | (u.v) I + u v^T - v u^T - w [v]x ],  q = (w, u).
Mat34 d_rot_dq(const Quat4& q, const Eigen::Vector3d& v) {
    const double w = q(0);
    const Eigen::Vector3d u = q.tail<3>();
    Mat34 j;
    j.col(0) = 2.0 * (w * v + u.cross(v));
    j.rightCols<3>() = 2.0 * (u.dot(v) * Eigen::Matrix3d::Identity() + u * v.transpose() - v * u.transpose() -
                              w * math::skew(v));
    return j;
}

// Same expression with u -> -u (q* in place of q), chain rule through the sign of u.
Mat34 d_rot_t_dq(const Quat4& q, const Eigen::Vector3d& v) {
    const double w = q(0);
    const Eigen::Vector3d u = q.tail<3>();
    Mat34 j;
    j.col(0) = 2.0 * (w * v - u.cross(v));
    j.rightCols<3>() = 2.0 * (u.dot(v) * Eigen::Matrix3d::Identity() + u * v.transpose() - v * u.transpose() +
                              w * math::skew(v));
    return j;
}

Eigen::Matrix4d omega_right(const Eigen::Vector3d& w) {
    Eigen::Matrix4d m;
    m << 0.0, -w.x(), -w.y(), -w.z(),  //
        w.x(), 0.0, w.z(), -w.y(),     //
        w.y(), -w.z(), 0.0, w.x(),     //
        w.z(), w.y(), -w.x(), 0.0;
    return m;
}

Mat43 xi(const Quat4& q) {
    Mat43 m;
    m << -q(1), -q(2), -q(3),  //
        q(0), -q(3), q(2),     //
        q(3), q(0), -q(1),     //
        -q(2), q(1), q(0);
    return m;
}

Quat4 quat_kinematics(const Quat4& q, const Eigen::Vector3d& w) { return 0.5 * (xi(q) * w); }

// dq (x) p with p = q_est* = (w, -u): right-multiplication matrix of p, vector rows: [p_v | p_w I - [p_v]x].
Mat34 att_error_jacobian(const Quat4& q_est) {
    const double w = q_est(0);
    const Eigen::Vector3d pv = -q_est.tail<3>();
    Mat34 g;
    g.col(0) = 2.0 * pv;
    g.rightCols<3>() = 2.0 * (w * Eigen::Matrix3d::Identity() - math::skew(pv));
    return g;
}

}  // namespace gdnav::core::filters
