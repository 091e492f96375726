// Every observation and state-transition Jacobian of the navigation filters against central differences
// (acceptance: row-wise relative error <= 1e-6, several random states each).
#include <gtest/gtest.h>

#include "air_data_filter.hpp"
#include "attitude_model.hpp"
#include "denied_rules.hpp"
#include "filters/numerical_jacobian.hpp"
#include "gnss_aided_model.hpp"
#include "math/rotation.hpp"
#include "nav_earth.hpp"
#include "nav_test_util.hpp"

using namespace gdnav;
using namespace gdnav::nav;
using test::rowwise_relative_error;

namespace {
constexpr double kTol = 1e-6;

att::StateVec random_att_state(rnd::Stream& s, bool unit_q) {
    att::StateVec x;
    Eigen::Vector4d q(s.normal(), s.normal(), s.normal(), s.normal());
    x.segment<4>(att::kQ) = unit_q ? Eigen::Vector4d(q.normalized()) : q;
    x.segment<3>(att::kW) = 0.3 * s.normal3();
    x.segment<3>(att::kEgyr) = 0.01 * s.normal3();
    x.segment<3>(att::kEmag) = 500.0 * s.normal3();
    x.segment<3>(att::kBdev) = 150.0 * s.normal3();
    return x;
}

PositionEstimate random_position(rnd::Stream& s) {
    PositionEstimate p;
    p.lon_rad = s.uniform(-math::kPi, math::kPi);
    p.lat_rad = s.uniform(-1.2, 1.2);
    p.h_m = s.uniform(0.0, 5000.0);
    p.v_n_mps = 30.0 * s.normal3();
    p.wind_n_mps = 8.0 * s.normal3();
    p.acc_err_b_mps2 = 0.2 * s.normal3();
    return p;
}
}  // namespace

TEST(NavJacobians, AirDataObservationAndTransition) {
    rnd::Stream s(21);
    for (int i = 0; i < 10; ++i) {
        AirDataFilter::StateVec x;
        x << s.uniform(15, 50), s.normal(0, 0.1), s.normal(0, 0.1), s.uniform(230, 310), s.uniform(-300, 8000),
            s.normal(0, 3), s.normal(0, 1), s.normal(0, 0.1), s.normal(0, 0.1);
        auto h = [](const AirDataFilter::StateVec& v) { return AirDataFilter::observe(v); };
        auto f = [](const AirDataFilter::StateVec& v) { return AirDataFilter::derivative(v); };
        EXPECT_LE(rowwise_relative_error(AirDataFilter::observation_jacobian(x),
                                         filters::numerical_jacobian<5, 9>(h, x)),
                  kTol);
        EXPECT_LE(rowwise_relative_error(AirDataFilter::state_jacobian(), filters::numerical_jacobian<9, 9>(f, x)),
                  kTol);
    }
}

TEST(NavJacobians, AttitudeTransition) {
    rnd::Stream s(22);
    for (int i = 0; i < 10; ++i) {
        const att::StateVec x = random_att_state(s, i % 2 == 0);
        auto f = [](const att::StateVec& v) { return att::derivative(v); };
        const att::StateCov a = att::state_jacobian(x);
        EXPECT_LE(rowwise_relative_error(a, filters::numerical_jacobian<16, 16>(f, x)), kTol);
        // The filter propagates with the leading block only: everything outside it must be zero.
        att::StateCov outside = a;
        outside.topLeftCorner<att::kJ, att::kJ>().setZero();
        EXPECT_EQ(outside.cwiseAbs().maxCoeff(), 0.0);
    }
}

TEST(NavJacobians, AttitudeObservationAllVariants) {
    rnd::Stream s(23);
    const att::SpecificForceModel models[] = {att::SpecificForceModel::kBaseline,
                                              att::SpecificForceModel::kZeroBodyDerivatives,
                                              att::SpecificForceModel::kZeroNedDerivatives};
    for (const auto m : models) {
        for (int i = 0; i < 10; ++i) {
            const att::StateVec x = random_att_state(s, i % 2 == 0);
            const att::PnVector pn = att::make_pn(random_position(s));
            auto h = [&](const att::StateVec& v) { return att::observe(v, pn, m); };
            const att::MeasJac num = filters::numerical_jacobian<9, 16>(h, x);
            EXPECT_LE(rowwise_relative_error(att::observation_jacobian(x, pn, m), num), kTol)
                << "model " << static_cast<int>(m) << " sample " << i;
        }
    }
}

TEST(NavJacobians, AttitudeVariantsDifferOnlyInTheCouplingTerm) {
    rnd::Stream s(24);
    const att::StateVec x = random_att_state(s, true);
    const att::PnVector pn = att::make_pn(random_position(s));
    const att::MeasVec yb = att::observe(x, pn, att::SpecificForceModel::kBaseline);
    const att::MeasVec yfb = att::observe(x, pn, att::SpecificForceModel::kZeroBodyDerivatives);
    const att::MeasVec yfn = att::observe(x, pn, att::SpecificForceModel::kZeroNedDerivatives);
    // Gyro and magnetometer rows identical; accelerometer rows differ by w x R^T(...) as the paper's equations.
    EXPECT_EQ((yb - yfb).head<3>().norm(), 0.0);
    EXPECT_EQ((yb - yfb).tail<3>().norm(), 0.0);
    const Eigen::Vector3d w = x.segment<3>(att::kW);
    const Eigen::Matrix3d rt = math::from_wxyz(x.segment<4>(att::kQ)).toRotationMatrix().transpose();
    EXPECT_LT((yb.segment<3>(3) - yfn.segment<3>(3) - w.cross(rt * (pn.v_n - pn.wind_n))).norm(), 1e-12);
    EXPECT_LT((yfb.segment<3>(3) - yfn.segment<3>(3) - w.cross(rt * pn.v_n)).norm(), 1e-12);
}

TEST(NavJacobians, GnssAidedTransitionAndObservations) {
    rnd::Stream s(25);
    for (int i = 0; i < 10; ++i) {
        aided::StateVec x;
        x << s.uniform(-3.0, 3.0), s.uniform(-1.2, 1.2), s.uniform(0.0, 5000.0), 30.0 * s.normal3(),
            5.0 * s.normal3(), 0.2 * s.normal3();
        const Quat q = math::quat_from_rotv(s.normal3());
        auto f = [&](const aided::StateVec& v) { return aided::derivative(v, q); };
        const aided::StateCov a = aided::state_jacobian(x, q);
        EXPECT_LE(rowwise_relative_error(a, filters::numerical_jacobian<12, 12>(f, x)), kTol) << "sample " << i;
        aided::StateCov outside = a;
        outside.topLeftCorner<aided::kJ, aided::kJ>().setZero();
        EXPECT_EQ(outside.cwiseAbs().maxCoeff(), 0.0);
        auto hf = [](const aided::StateVec& v) { return aided::observe_fast(v); };
        auto hs = [](const aided::StateVec& v) { return aided::observe_slow(v); };
        EXPECT_LE(rowwise_relative_error(aided::jacobian_fast(), filters::numerical_jacobian<3, 12>(hf, x)), kTol);
        EXPECT_LE(rowwise_relative_error(aided::jacobian_slow(), filters::numerical_jacobian<9, 12>(hs, x)), kTol);
    }
}

TEST(NavJacobians, AirspeedDerivativeIsTimeDerivativeOfAirspeedVector) {
    // vtas_dot_body must be d/dt vtas_body(v(t), a(t), b(t)) (used by the wind-integration variant).
    rnd::Stream s(26);
    for (int i = 0; i < 10; ++i) {
        const Eigen::Vector3d x0(s.uniform(15, 50), s.normal(0, 0.2), s.normal(0, 0.2));
        const Eigen::Vector3d xd(s.normal(0, 1), s.normal(0, 0.1), s.normal(0, 0.1));
        auto g = [&](const filters::Vec<1>& t) {
            const Eigen::Vector3d v = x0 + t(0) * xd;
            return math::vtas_body(v.x(), v.y(), v.z());
        };
        const filters::Vec<1> t0 = filters::Vec<1>::Zero();
        const Eigen::Vector3d num = filters::numerical_jacobian<3, 1>(g, t0);
        const Eigen::Vector3d ana = denied::vtas_dot_body(x0.x(), x0.y(), x0.z(), xd.x(), xd.y(), xd.z());
        EXPECT_LE((ana - num).cwiseAbs().maxCoeff() / num.cwiseAbs().maxCoeff(), kTol);
    }
}

TEST(NavJacobians, EarthHelperDerivatives) {
    // Radii and gravity derivatives used inside the GNSS-aided Jacobian.
    rnd::Stream s(27);
    for (int i = 0; i < 10; ++i) {
        filters::Vec<2> x(s.uniform(-1.4, 1.4), s.uniform(0.0, 8000.0));
        auto f = [](const filters::Vec<2>& v) {
            const nav::earth::Radii r = nav::earth::radii(v(0));
            return Eigen::Vector3d(r.n_m, r.m_m, nav::earth::normal_gravity(v(0), v(1)).g_mps2);
        };
        const nav::earth::Radii r = nav::earth::radii(x(0));
        const nav::earth::Gravity g = nav::earth::normal_gravity(x(0), x(1));
        Eigen::Matrix<double, 3, 2> ana;
        ana << r.dn_dlat, 0.0, r.dm_dlat, 0.0, g.dg_dlat, g.dg_dh;
        EXPECT_LE(rowwise_relative_error(ana, filters::numerical_jacobian<3, 2>(f, x)), kTol);
    }
}
