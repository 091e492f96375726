// EKF toolkit (common/core/filters): quaternion Jacobians vs central differences, transition matrix vs the matrix
// exponential, Joseph update vs the closed-form scalar Kalman filter.
#include <gtest/gtest.h>

#include <unsupported/Eigen/MatrixFunctions>

#include "filters/ekf.hpp"
#include "filters/numerical_jacobian.hpp"
#include "filters/quat_jacobians.hpp"
#include "math/rotation.hpp"
#include "nav_test_util.hpp"

using namespace gdnav;
using filters::Quat4;

namespace {
Quat4 random_quat4(rnd::Stream& s, bool unit) {
    Quat4 q(s.normal(), s.normal(), s.normal(), s.normal());
    if (unit) q.normalize();
    return q;
}
}  // namespace

TEST(NavEkf, QuadraticRotationEqualsEigenForUnitQuaternions) {
    rnd::Stream s(11);
    for (int i = 0; i < 20; ++i) {
        const Quat4 q = random_quat4(s, true);
        const Eigen::Matrix3d r = math::from_wxyz(q).toRotationMatrix();
        EXPECT_LT((filters::rot_quadratic(q) - r).cwiseAbs().maxCoeff(), 1e-14);
        const Eigen::Vector3d v = s.normal3();
        EXPECT_LT((filters::rotate(q, v) - math::from_wxyz(q) * v).norm(), 1e-13);
        EXPECT_LT((filters::rotate_back(q, v) - math::from_wxyz(q).conjugate() * v).norm(), 1e-13);
    }
}

TEST(NavEkf, QuaternionJacobiansMatchCentralDifferences) {
    rnd::Stream s(12);
    for (int i = 0; i < 25; ++i) {
        const Quat4 q = random_quat4(s, i % 2 == 0);  // unit and non-unit 4-vectors
        const Eigen::Vector3d v = 10.0 * s.normal3();
        const Eigen::Vector3d w = 0.3 * s.normal3();
        auto fr = [&](const Quat4& x) { return filters::rotate(x, v); };
        auto fb = [&](const Quat4& x) { return filters::rotate_back(x, v); };
        auto fk = [&](const Quat4& x) { return filters::quat_kinematics(x, w); };
        auto fkw = [&](const Eigen::Vector3d& x) { return filters::quat_kinematics(q, x); };
        EXPECT_LE(filters::relative_error(filters::d_rot_dq(q, v), filters::numerical_jacobian<3, 4>(fr, q)), 1e-6);
        EXPECT_LE(filters::relative_error(filters::d_rot_t_dq(q, v), filters::numerical_jacobian<3, 4>(fb, q)), 1e-6);
        EXPECT_LE(filters::relative_error(Eigen::Matrix4d(0.5 * filters::omega_right(w)),
                                          filters::numerical_jacobian<4, 4>(fk, q)),
                  1e-6);
        EXPECT_LE(filters::relative_error(filters::Mat43(0.5 * filters::xi(q)), filters::numerical_jacobian<4, 3>(fkw, w)),
                  1e-6);
    }
}

TEST(NavEkf, KinematicsMatchesQuaternionProduct) {
    // 0.5 q (x) [0, w] computed with Eigen's Hamilton product.
    rnd::Stream s(13);
    const Quat4 q = random_quat4(s, true);
    const Eigen::Vector3d w = s.normal3();
    const Eigen::Quaterniond p = math::from_wxyz(q) * Eigen::Quaterniond(0.0, w.x(), w.y(), w.z());
    EXPECT_LT((filters::quat_kinematics(q, w) - 0.5 * math::to_wxyz(p)).norm(), 1e-15);
    EXPECT_LT((filters::quat_kinematics(q, w) - math::quat_derivative(math::from_wxyz(q), w)).norm(), 1e-15);
}

TEST(NavEkf, AttitudeErrorJacobianGivesNedSideAngle) {
    // q_true = dq(dtheta_n) (x) q_est  =>  G (q_true - q_est) ~ dtheta_n for a small dtheta.
    rnd::Stream s(14);
    const Quat4 qe = random_quat4(s, true);
    const Eigen::Vector3d dth(1e-5, -2e-5, 3e-5);
    const Quat4 qt = math::to_wxyz(math::quat_from_rotv(dth) * math::from_wxyz(qe));
    EXPECT_LT((filters::att_error_jacobian(qe) * (qt - qe) - dth).norm(), 1e-9);
}

TEST(NavEkf, TransitionMatrixConvergesToMatrixExponential) {
    rnd::Stream s(15);
    Eigen::Matrix<double, 6, 6> a;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) a(i, j) = s.normal();
    const double dt = 0.01;
    const Eigen::Matrix<double, 6, 6> ex = (a * dt).exp();
    const double e1 = (filters::transition_matrix<6>(a, dt, 1) - ex).cwiseAbs().maxCoeff();
    const double e2 = (filters::transition_matrix<6>(a, dt, 2) - ex).cwiseAbs().maxCoeff();
    const double e4 = (filters::transition_matrix<6>(a, dt, 4) - ex).cwiseAbs().maxCoeff();
    // Truncation error of order n is ~ |A dt|^(n+1)/(n+1)!, |A dt| ~ 0.03 here.
    EXPECT_LT(e1, 1e-3);
    EXPECT_LT(e2, 1e-5);
    EXPECT_LT(e4, 1e-10);
    EXPECT_LT(e2, e1);
    EXPECT_LT(e4, e2);
}

TEST(NavEkf, JosephUpdateMatchesScalarKalmanFilter) {
    // Scalar random constant: P+ = P R / (P + R), x+ = x + P/(P+R) (y - x).
    filters::Vec<1> x;
    x << 2.0;
    filters::SqMat<1> p;
    p << 4.0;
    filters::Mat<1, 1> h;
    h << 1.0;
    filters::Vec<1> r;
    r << 1.0;
    filters::Vec<1> innov;
    innov << 3.0 - 2.0;
    const auto info = filters::joseph_update_diag<1, 1>(x, p, innov, h, r);
    EXPECT_TRUE(info.ok);
    EXPECT_NEAR(x(0), 2.0 + 0.8 * 1.0, 1e-15);
    EXPECT_NEAR(p(0, 0), 4.0 * 1.0 / 5.0, 1e-15);
    EXPECT_NEAR(info.nis, 1.0 / 5.0, 1e-15);
}

TEST(NavEkf, JosephUpdateMatchesInformationForm) {
    // P+^-1 = P^-1 + H^T R^-1 H, x+ = x + P+ H^T R^-1 r for a random linear problem (independent formula).
    rnd::Stream s(16);
    filters::SqMat<4> l;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) l(i, j) = s.normal();
    filters::SqMat<4> p = l * l.transpose() + filters::SqMat<4>::Identity();
    filters::Mat<2, 4> h;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 4; ++j) h(i, j) = s.normal();
    filters::Vec<2> rd(0.5, 2.0);
    filters::Vec<4> x = filters::Vec<4>::Zero();
    filters::Vec<2> innov(1.0, -2.0);
    const filters::SqMat<4> p_info =
        (p.inverse() + h.transpose() * rd.cwiseInverse().asDiagonal() * h).inverse();
    const filters::Vec<4> x_info = p_info * h.transpose() * rd.cwiseInverse().asDiagonal() * innov;
    filters::joseph_update_diag<4, 2>(x, p, innov, h, rd);
    EXPECT_LT((p - p_info).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT((x - x_info).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(NavEkf, PropagateCovarianceIsPhiPPhiTPlusQ) {
    filters::SqMat<2> p;
    p << 2.0, 0.5, 0.5, 1.0;
    filters::SqMat<2> phi;
    phi << 1.0, 0.1, 0.0, 1.0;
    filters::propagate_covariance_diag<2>(p, phi, filters::Vec<2>(0.01, 0.02));
    // By hand: [[2 + 2*0.1*0.5 + 0.01*1 + 0.01, 0.5 + 0.1], [0.6, 1.02]]
    EXPECT_NEAR(p(0, 0), 2.11 + 0.01, 1e-15);
    EXPECT_NEAR(p(0, 1), 0.6, 1e-15);
    EXPECT_NEAR(p(1, 0), 0.6, 1e-15);
    EXPECT_NEAR(p(1, 1), 1.02, 1e-15);
}

TEST(NavEkf, LeadingBlockPropagationEqualsDense) {
    rnd::Stream s(17);
    filters::SqMat<7> l;
    for (int i = 0; i < 7; ++i)
        for (int j = 0; j < 7; ++j) l(i, j) = s.normal();
    filters::SqMat<7> p = l * l.transpose();
    filters::SqMat<3> phik;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) phik(i, j) = (i == j ? 1.0 : 0.0) + 0.1 * s.normal();
    filters::SqMat<7> phi = filters::SqMat<7>::Identity();
    phi.topLeftCorner<3, 3>() = phik;
    filters::Vec<7> q = filters::Vec<7>::Constant(0.01);
    filters::SqMat<7> p_dense = p, p_block = p;
    filters::propagate_covariance_diag<7>(p_dense, phi, q);
    filters::propagate_covariance_leading_diag<7, 3>(p_block, phik, q);
    EXPECT_LT((p_dense - p_block).cwiseAbs().maxCoeff(), 1e-13);
}
