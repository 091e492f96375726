// Error-state (multiplicative) attitude filter (components/nav/model/eskf_attitude.hpp):
//   * its observation Jacobian is the derivative of att::observe with respect to the injected error (central
//     differences through eskf::inject), for the three specific-force variants;
//   * the transition is the derivative of the nominal propagation with respect to the error;
//   * the injection leaves a unit quaternion and the reset keeps P symmetric positive definite;
//   * from a 5 deg initial error it converges like the additive filter on a synthetic turn (perfect p_n).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "attitude_filter.hpp"
#include "eskf_attitude.hpp"
#include "filters/numerical_jacobian.hpp"
#include "math/rotation.hpp"
#include "nav_chain.hpp"
#include "nav_test_util.hpp"

using namespace gdnav;
using namespace gdnav::nav;
using test::rowwise_relative_error;

namespace {

att::StateVec random_state(rnd::Stream& s) {
    att::StateVec x;
    const Eigen::Vector4d q(s.normal(), s.normal(), s.normal(), s.normal());
    x.segment<4>(att::kQ) = q.normalized();
    x.segment<3>(att::kW) = 0.3 * s.normal3();
    x.segment<3>(att::kEgyr) = 0.01 * s.normal3();
    x.segment<3>(att::kEmag) = 500.0 * s.normal3();
    x.segment<3>(att::kBdev) = 150.0 * s.normal3();
    return x;
}

att::PnVector random_pn(rnd::Stream& s) {
    PositionEstimate p;
    p.lon_rad = s.uniform(-math::kPi, math::kPi);
    p.lat_rad = s.uniform(-1.2, 1.2);
    p.h_m = s.uniform(0.0, 5000.0);
    p.v_n_mps = 30.0 * s.normal3();
    p.wind_n_mps = 8.0 * s.normal3();
    p.acc_err_b_mps2 = 0.2 * s.normal3();
    return att::make_pn(p);
}

// The nominal state after injecting dx (covariance discarded).
att::StateVec injected(const att::StateVec& x, const eskf::ErrVec& dx) {
    att::StateVec y = x;
    eskf::ErrCov p = eskf::ErrCov::Identity();
    eskf::inject(y, p, dx);
    return y;
}

}  // namespace

TEST(NavEskf, ObservationJacobianIsTheDerivativeWithRespectToTheInjectedError) {
    rnd::Stream s(61);
    for (const auto m : {att::SpecificForceModel::kBaseline, att::SpecificForceModel::kZeroBodyDerivatives,
                         att::SpecificForceModel::kZeroNedDerivatives}) {
        for (int i = 0; i < 10; ++i) {
            const att::StateVec x = random_state(s);
            const att::PnVector pn = random_pn(s);
            auto h = [&](const eskf::ErrVec& dx) { return att::observe(injected(x, dx), pn, m); };
            // Steps of 1e-6 on every error component (angles in rad, biases in their units).
            const eskf::ErrJac num =
                filters::numerical_jacobian<att::kM, eskf::kN>(h, eskf::ErrVec::Zero().eval(), 1e-6, 1.0);
            EXPECT_LE(rowwise_relative_error(eskf::observation_jacobian(x, pn, m), num), 1e-6)
                << "model " << static_cast<int>(m) << " sample " << i;
        }
    }
}

TEST(NavEskf, TransitionIsTheDerivativeOfTheNominalPropagation) {
    // Error after one Euler step of the nominal model, dtheta(k+1) = dtheta + dt R dw (+ O(dt^2)), compared with the
    // NED-side difference of the propagated true and nominal quaternions.
    rnd::Stream s(62);
    const double dt = 0.01;
    for (int i = 0; i < 10; ++i) {
        const att::StateVec x = random_state(s);
        const Eigen::Matrix<double, 6, 6> phi = eskf::transition_leading(x, dt);
        auto step = [&](const att::StateVec& v) {
            att::StateVec n = v + dt * att::derivative(v);
            n.segment<4>(att::kQ).normalize();
            return n;
        };
        const att::StateVec xn = step(x);
        auto err_after = [&](const Eigen::Matrix<double, 6, 1>& d) {
            eskf::ErrVec dx = eskf::ErrVec::Zero();
            dx.head<6>() = d;
            const att::StateVec tn = step(injected(x, dx));
            const math::Quat dq = math::from_wxyz(tn.segment<4>(att::kQ)) *
                                  math::from_wxyz(xn.segment<4>(att::kQ)).conjugate();
            Eigen::Matrix<double, 6, 1> e;
            e << math::rotv_from_quat(dq), tn.segment<3>(att::kW) - xn.segment<3>(att::kW);
            return e;
        };
        const Eigen::Matrix<double, 6, 6> num =
            filters::numerical_jacobian<6, 6>(err_after, Eigen::Matrix<double, 6, 1>::Zero().eval(), 1e-6, 1.0);
        // Phi = I + A dt is exact for the continuous error model; the Euler step differs by O(dt^2 |w|).
        EXPECT_LT((phi - num).cwiseAbs().maxCoeff(), 2e-2 * dt) << i;
    }
}

TEST(NavEskf, InjectionKeepsAUnitQuaternionAndAPositiveDefiniteCovariance) {
    rnd::Stream s(63);
    for (int i = 0; i < 20; ++i) {
        att::StateVec x = random_state(s);
        eskf::ErrVec dx = 0.05 * eskf::ErrVec::Random();
        Eigen::Matrix<double, eskf::kN, eskf::kN> a = Eigen::Matrix<double, eskf::kN, eskf::kN>::Random();
        eskf::ErrCov p = a * a.transpose() + 1e-3 * eskf::ErrCov::Identity();
        const math::Quat q0 = math::from_wxyz(x.segment<4>(att::kQ));
        eskf::inject(x, p, dx);
        const math::Quat q1 = math::from_wxyz(x.segment<4>(att::kQ));
        EXPECT_NEAR(x.segment<4>(att::kQ).norm(), 1.0, 1e-15);
        // The applied rotation is dtheta on the NED side: q1 q0* = Exp(dtheta).
        EXPECT_LT((math::rotv_from_quat(q1 * q0.conjugate()) - dx.head<3>()).norm(), 1e-12);
        EXPECT_EQ((p - p.transpose()).cwiseAbs().maxCoeff(), 0.0);
        EXPECT_EQ(Eigen::LLT<eskf::ErrCov>(p).info(), Eigen::Success);
    }
}

TEST(NavEskf, ConvergesFromLargeInitialAttitudeErrorLikeTheAdditiveFilter) {
    // As NavAttitude.ConvergesFromLargeInitialAttitudeError: 5 deg initial error with a consistent P0, biases known to
    // 1 %, repository Q and R, a 2.9 deg/s turn with wind, perfect p_n of the previous step; both formulations.
    double final_deg[2] = {0.0, 0.0};
    for (int form = 0; form < 2; ++form) {
        rnd::Stream s(45);
        const config::Config tuning =
            config::Config::wrap(test::load_tuning_node(true)["attitude"], "tuning.yaml");
        const config::Config variant = config::Config::parse(
            form == 0 ? "specific_force: baseline\n" : "specific_force: baseline\nfilter: error_state\n", "variant");
        AttitudeFilter f;
        f.configure(tuning, variant, s.child("f"));
        ASSERT_EQ(f.tuning().formulation == AttitudeFormulation::kErrorState, form == 1);
        synth::Scenario sc;
        sc.yaw_rate_rps = 0.05;
        sc.bank_rad = std::atan(0.05 * 30.0 / 9.8);
        sc.wind_n_mps = {4.0, -6.0, 0.0};
        sc.gyr_err_b_rps = 3.49e-3 * s.normal3();
        sc.mag_err_b_nT = 530.0 * s.normal3();
        sc.b_dev_n_nT = Eigen::Vector3d(138, 89, 165).cwiseProduct(s.normal3());
        synth::Generator gen(sc, s.child("data"));
        synth::Sample smp = gen.next();
        AttitudeInit in;
        in.q_nb = math::quat_from_rotv(math::deg2rad(5.0) * Eigen::Vector3d(0.6, -0.48, 0.64)) * smp.truth.q_nb;
        in.att_sigma_rad = math::deg2rad(5.0);
        in.gyr_bias_rps = sc.gyr_err_b_rps * 1.01;
        in.mag_bias_nT = sc.mag_err_b_nT * 1.01;
        in.b_dev_n_nT = sc.b_dev_n_nT * 1.1;
        in.gyr_bias_sigma_rps = 0.01 * sc.gyr_err_b_rps.cwiseAbs();
        in.mag_bias_sigma_nT = 0.01 * sc.mag_err_b_nT.cwiseAbs();
        in.b_dev_sigma_nT = 0.1 * sc.b_dev_n_nT.cwiseAbs();
        in.w_nb_b_rps = smp.imu.w_b_rps - in.gyr_bias_rps;
        in.w_nb_sigma_rps = Eigen::Vector3d::Constant(1e-3);
        f.initialize(0, 0.0, in);
        // The initial attitude covariance is the same rotation-angle covariance in both formulations.
        EXPECT_NEAR(f.attitude_covariance_n().trace(), 3.0 * std::pow(math::deg2rad(5.0), 2), 1e-9);
        for (int k = 1; k <= 12000; ++k) {  // 120 s
            PositionEstimate pn;
            pn.lon_rad = smp.truth.lon_rad;
            pn.lat_rad = smp.truth.lat_rad;
            pn.h_m = smp.truth.h_m;
            pn.v_n_mps = smp.truth.v_n_mps;
            pn.wind_n_mps = sc.wind_n_mps;
            pn.acc_err_b_mps2 = sc.acc_err_b_mps2;
            smp = gen.next();
            f.step(static_cast<std::uint64_t>(k), smp.truth.t_s, smp.imu, smp.mag, pn);
        }
        final_deg[form] = math::rad2deg(math::angle_between(f.estimate_q(), smp.truth.q_nb));
        EXPECT_LT(final_deg[form], 0.2) << "formulation " << form;
    }
    std::printf("attitude error after 120 s from 5 deg: additive %.4f deg, error-state %.4f deg\n", final_deg[0],
                final_deg[1]);
}
