// Attitude filter on synthetic constant-rate turns: NEES consistency with a matched tuning, convergence from a
// large initial error and the coarse alignment of init.mode measurements (the alignment error model is tested
// with the sensors, tests/unit/sensors/alignment_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "nav_chain.hpp"

using namespace gdnav;
using namespace gdnav::nav;

namespace {

// Wilson-Hilferty approximation of the chi-square quantile with k dof for the standard normal quantile z.
double chi2_quantile(double k, double z) {
    const double a = 2.0 / (9.0 * k);
    return k * std::pow(1.0 - a + z * std::sqrt(a), 3.0);
}

synth::Scenario turn_scenario() {
    synth::Scenario sc;
    sc.yaw_rate_rps = 0.05;                      // 2.9 deg/s turn
    sc.bank_rad = std::atan(0.05 * 30.0 / 9.8);  // coordinated bank (8.7 deg)
    sc.wind_n_mps = {4.0, -6.0, 0.0};
    return sc;
}

// Perfect p_n: the position estimate the attitude filter would get from an ideal position filter.
PositionEstimate perfect_pn(const synth::Sample& s, const synth::Scenario& sc) {
    PositionEstimate p;
    p.lon_rad = s.truth.lon_rad;
    p.lat_rad = s.truth.lat_rad;
    p.h_m = s.truth.h_m;
    p.v_n_mps = s.truth.v_n_mps;
    p.wind_n_mps = sc.wind_n_mps;
    p.acc_err_b_mps2 = sc.acc_err_b_mps2;
    return p;
}

}  // namespace

TEST(NavAttitude, NeesIsConsistentOnConstantRateTurn) {
    // Matched tuning: R = the synthetic sensors' white-noise variances, truth = model (constant biases, constant
    // rate, exact specific-force equation), initial errors drawn from P0, perfect p_n. Then the attitude NEES
    // e^T C^-1 e (3 dof) at the end of each of N independent runs is chi-square(3) and their sum chi-square(3N).
    const int runs = 50;
    const int steps = 3000;  // 30 s
    const double sig_att0 = math::deg2rad(0.5);
    const Eigen::Vector3d sig_gyr0 = Eigen::Vector3d::Constant(1e-3);
    const Eigen::Vector3d sig_mag0 = Eigen::Vector3d::Constant(100.0);
    const Eigen::Vector3d sig_bdev0 = Eigen::Vector3d::Constant(50.0);
    double sum_att = 0.0, sum_gyr = 0.0;
    for (int run = 0; run < runs; ++run) {
        rnd::Stream s = rnd::Stream::derive(7, static_cast<std::uint64_t>(run), "nees");
        synth::Scenario sc = turn_scenario();
        sc.gyr_err_b_rps = 3.49e-3 * s.normal3();
        sc.acc_err_b_mps2 = 0.157 * s.normal3();
        sc.mag_err_b_nT = 530.0 * s.normal3();
        sc.b_dev_n_nT = Eigen::Vector3d(138, 89, 165).cwiseProduct(s.normal3());
        AttitudeFilter::Tuning tun;
        tun.q_diag.segment<4>(att::kQ).setConstant(1e-15);
        tun.q_diag.segment<3>(att::kW).setConstant(1e-10);
        tun.q_diag.segment<3>(att::kEgyr).setConstant(1e-16);
        tun.q_diag.segment<3>(att::kEmag).setConstant(1e-10);
        tun.q_diag.segment<3>(att::kBdev).setConstant(1e-10);
        tun.r_diag << Eigen::Vector3d::Constant(sc.gyr_sigma_rps * sc.gyr_sigma_rps),
            Eigen::Vector3d::Constant(sc.acc_sigma_mps2 * sc.acc_sigma_mps2),
            Eigen::Vector3d::Constant(sc.mag_sigma_nT * sc.mag_sigma_nT);
        AttitudeFilter f;
        f.configure(tun, s.child("filter"));
        synth::Generator gen(sc, s.child("data"));
        synth::Sample s0 = gen.next();
        AttitudeInit in;
        in.q_nb = math::quat_from_rotv(sig_att0 * s.normal3()) * s0.truth.q_nb;
        in.att_sigma_rad = sig_att0;
        in.gyr_bias_rps = sc.gyr_err_b_rps + sig_gyr0.cwiseProduct(s.normal3());
        in.mag_bias_nT = sc.mag_err_b_nT + sig_mag0.cwiseProduct(s.normal3());
        in.b_dev_n_nT = sc.b_dev_n_nT + sig_bdev0.cwiseProduct(s.normal3());
        in.gyr_bias_sigma_rps = sig_gyr0;
        in.mag_bias_sigma_nT = sig_mag0;
        in.b_dev_sigma_nT = sig_bdev0;
        // w_nb0 = true rate + N(0, P0): a consistent initial rate.
        const Eigen::Vector3d sig_w0 = Eigen::Vector3d::Constant(1e-3);
        in.w_nb_b_rps = s0.truth.w_nb_b_rps + sig_w0.cwiseProduct(s.normal3());
        in.w_nb_sigma_rps = sig_w0;
        f.initialize(0, 0.0, in);
        for (int k = 1; k <= steps; ++k) {
            const synth::Sample smp = gen.next();
            f.step(static_cast<std::uint64_t>(k), smp.truth.t_s, smp.imu, smp.mag, perfect_pn(smp, sc));
            if (k == steps) {
                const Eigen::Vector3d e = math::rotv_from_quat(smp.truth.q_nb * f.estimate_q().conjugate());
                sum_att += e.dot(f.attitude_covariance_n().ldlt().solve(e));
                const Eigen::Vector3d eg = f.state().segment<3>(att::kEgyr) - sc.gyr_err_b_rps;
                sum_gyr += eg.dot(f.covariance().block<3, 3>(att::kEgyr, att::kEgyr).ldlt().solve(eg));
            }
        }
    }
    const double k = 3.0 * runs;
    // 99 % two-sided band of chi-square(150)/50 (Wilson-Hilferty): [2.18, 3.97].
    const double lo = chi2_quantile(k, -2.5758) / runs, hi = chi2_quantile(k, 2.5758) / runs;
    EXPECT_GT(sum_att / runs, lo);
    EXPECT_LT(sum_att / runs, hi);
    EXPECT_GT(sum_gyr / runs, lo);
    EXPECT_LT(sum_gyr / runs, hi);
    RecordProperty("mean_nees_attitude", std::to_string(sum_att / runs));
    RecordProperty("mean_nees_gyro_bias", std::to_string(sum_gyr / runs));
}

TEST(NavAttitude, ReferenceTuningTracksATurnToWithin0p15Degrees) {
    // Repository tuning (reference Q, R), reference initialisation, realistic constant sensor errors, the whole
    // chain (p_n from the GNSS-aided position filter of the previous step) during a 300 s constant-rate turn.
    rnd::Stream s(43);
    synth::Scenario sc = turn_scenario();
    sc.gyr_err_b_rps = 3.49e-3 * s.normal3();
    sc.acc_err_b_mps2 = 0.157 * s.normal3();
    sc.mag_err_b_nT = 530.0 * s.normal3();
    sc.b_dev_n_nT = Eigen::Vector3d(138, 89, 165).cwiseProduct(s.normal3());
    test::ChainOptions o;
    o.steps = 30000;
    const test::ChainRun r = test::run_chain(sc, o, 44);
    double worst = 0.0;
    for (std::size_t k = 1000; k < r.att.size(); ++k) worst = std::max(worst, test::att_error(r, k));
    EXPECT_LT(math::rad2deg(worst), 0.15);
    EXPECT_LT((r.att.back().gyr_bias_rps - sc.gyr_err_b_rps).norm(), 1e-4);  // 3 % of the 3.5e-3 offset
}

TEST(NavAttitude, ConvergesFromLargeInitialAttitudeError) {
    // 5 deg initial error (consistent P0), biases known to 1 % as in the reference, repository Q and R.
    rnd::Stream s(45);
    const config::Config tuning = config::Config::wrap(test::load_tuning_node(true)["attitude"], "tuning.yaml");
    const config::Config variant = config::Config::parse("specific_force: baseline\n", "variant");
    AttitudeFilter f;
    f.configure(tuning, variant, s.child("f"));
    synth::Scenario sc = turn_scenario();
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
    const double e0 = math::angle_between(f.estimate_q(), smp.truth.q_nb);
    for (int k = 1; k <= 12000; ++k) {  // 120 s
        const PositionEstimate pn = perfect_pn(smp, sc);  // previous step's p_n, as in the architecture
        smp = gen.next();
        f.step(static_cast<std::uint64_t>(k), smp.truth.t_s, smp.imu, smp.mag, pn);
    }
    // Tilt converges in seconds; heading (magnetometer R = 2e5 nT^2) within ~100 s in the turn.
    EXPECT_NEAR(math::rad2deg(e0), 5.0, 1e-9);
    EXPECT_LT(math::rad2deg(math::angle_between(f.estimate_q(), smp.truth.q_nb)), 0.2);
}

// Tilt and heading sigmas apart (the truth-free start): the filter's attitude covariance about N, E, D is exactly
// diag(tilt^2, tilt^2, heading^2) at any attitude, in both formulations.
TEST(NavAttitude, TiltAndHeadingInitialSigmasAreTheCovarianceAboutNedAxes) {
    const config::Config tuning = config::Config::wrap(test::load_tuning_node(true)["attitude"], "tuning.yaml");
    for (const char* formulation : {"additive", "error_state"}) {
        SCOPED_TRACE(formulation);
        const config::Config variant =
            config::Config::parse(std::string("specific_force: baseline\nfilter: ") + formulation + "\n", "variant");
        AttitudeFilter f;
        f.configure(tuning, variant, rnd::Stream(46));
        AttitudeInit in;
        in.q_nb = math::quat_from_rotv(Eigen::Vector3d(0.3, -0.2, 2.1));  // banked, pitched, heading 120 deg
        in.att_sigma_rad = math::deg2rad(1.5);
        in.heading_sigma_rad = math::deg2rad(5.0);
        in.w_nb_sigma_rps = Eigen::Vector3d::Constant(1e-3);
        f.initialize(0, 0.0, in);
        const Eigen::Matrix3d p = f.attitude_covariance_n();
        const Eigen::Vector3d var(std::pow(math::deg2rad(1.5), 2), std::pow(math::deg2rad(1.5), 2),
                                  std::pow(math::deg2rad(5.0), 2));
        EXPECT_LT((p - Eigen::Matrix3d(var.asDiagonal())).cwiseAbs().maxCoeff(), 1e-12) << p;
    }
}

TEST(NavAttitude, CoarseAlignmentIsExactOnNoiseFreeData) {
    rnd::Stream s(46);
    for (int i = 0; i < 20; ++i) {
        const math::Euler e{s.uniform(-3.0, 3.0), s.uniform(-0.5, 0.5), s.uniform(-0.8, 0.8)};
        const Quat q = math::quat_from_euler(e);
        const Eigen::Vector3d b_n = nav::earth::magnetic_model_n(math::deg2rad(270.3), math::deg2rad(44.6));
        const Eigen::Vector3d f_b = q.conjugate() * Eigen::Vector3d(0.0, 0.0, -9.8);
        const Quat qc = coarse_attitude(f_b, q.conjugate() * b_n, b_n);
        EXPECT_LT(math::angle_between(q, qc), 1e-12);
    }
}

TEST(NavAttitude, TruthFreeInitialisationStaysBounded) {
    // init.mode measurements: coarse alignment from one sample and zero biases. The magnetic model deviation B_dev
    // and the heading are not separable by the magnetometer, and the accelerometer bias E_acc and tilt are not
    // separable in straight flight, so the error stays at the level of the unknown offsets (~1-2 deg), unlike the
    // reference initialisation (truth + 1 %/10 %) which the paper uses. Bound, not accuracy, is checked.
    rnd::Stream s(47);
    synth::Scenario sc = turn_scenario();
    sc.gyr_err_b_rps = 3.49e-3 * s.normal3();
    sc.acc_err_b_mps2 = 0.157 * s.normal3();
    sc.mag_err_b_nT = 530.0 * s.normal3();
    sc.b_dev_n_nT = Eigen::Vector3d(138, 89, 165).cwiseProduct(s.normal3());
    test::ChainOptions o;
    o.reference_init = false;
    o.steps = 20000;
    const test::ChainRun r = test::run_chain(sc, o, 48);
    double worst = 0.0;
    for (std::size_t k = 0; k < r.att.size(); ++k) worst = std::max(worst, test::att_error(r, k));
    EXPECT_LT(math::rad2deg(worst), 5.0);
    EXPECT_LT(math::rad2deg(test::att_error(r, r.att.size() - 1)), 3.0);
    EXPECT_LT((r.att.back().gyr_bias_rps - sc.gyr_err_b_rps).norm(), 5e-4);  // gyro offset 3.5e-3 learnt
}
