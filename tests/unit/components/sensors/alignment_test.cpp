// Pre-flight fine alignment emulation (components/sensors/model/alignment.hpp; docs/sensors.md, "Pre-flight fine
// alignment"): the attitude error spread with and without the reference's non-unit axis, the relative errors of
// the calibrated sensor errors and their published sigmas, determinism and the suite-file section.
#include <gtest/gtest.h>

#include <cmath>

#include "math/rotation.hpp"
#include "sensor_test_support.hpp"
#include "gnc/alignment.hpp"
#include "sensors/model/suite.hpp"

using namespace gdnav;
using namespace gdnav::sensors;
using math::Vec3;

TEST(Alignment, AttitudeErrorHasTheConfiguredSpread) {
    // gamma ~ N(0, sigma) about a unit axis: RMS angle = sigma. With the reference's non-unit axis
    // a = (cos p1 cos p2, sin p2, sin p1), E|a|^2 = 1 + E[sin^2 p1 sin^2 p2] = 1.25, so RMS = sigma sqrt(1.25).
    rnd::Stream s(41);
    const double sigma = math::deg2rad(0.1);
    const int n = 20000;
    double sum_unit = 0.0, sum_ref = 0.0;
    for (int i = 0; i < n; ++i) {
        sum_unit += std::pow(math::rotv_from_quat(draw_attitude_error(sigma, true, s)).norm(), 2);
        sum_ref += std::pow(math::rotv_from_quat(draw_attitude_error(sigma, false, s)).norm(), 2);
    }
    // Relative standard error of an RMS from n samples of a (scaled) chi-square(1): ~ sqrt(2/n)/2 = 0.5 %.
    EXPECT_NEAR(std::sqrt(sum_unit / n) / sigma, 1.0, 0.03);
    EXPECT_NEAR(std::sqrt(sum_ref / n) / sigma, std::sqrt(1.25), 0.04);
}

TEST(Alignment, EstimatesAreTruthWithTheRelativeErrorsAndPublishedSigmas) {
    const AlignmentErrors e;  // reference baseline: 0.1 deg, 1 %, 1 %, 1 %, 10 %
    const math::Quat q_true = math::quat_from_euler({0.7, 0.05, -0.1});
    const Vec3 gyr(3.0e-3, -2.0e-3, 1.0e-3), acc(0.1, -0.05, 0.2), mag(400.0, -300.0, 600.0), bdev(120.0, -80.0, 150.0);
    const int n = 4000;
    double s_att = 0.0, s_gyr = 0.0, s_acc = 0.0, s_mag = 0.0, s_bdev = 0.0;
    rnd::Stream st(7);
    for (int i = 0; i < n; ++i) {
        const ImuAlignment a = align_imu(e, q_true, gyr, acc, st);
        const MagAlignment m = align_mag(e, mag, bdev, st);
        s_att += std::pow(math::rotv_from_quat(a.q_nb * q_true.conjugate()).norm(), 2);
        // Relative errors per component are N(0, rel^2): pool the three axes.
        s_gyr += (a.gyr_err_rps - gyr).cwiseQuotient(gyr).squaredNorm() / 3.0;
        s_acc += (a.acc_err_mps2 - acc).cwiseQuotient(acc).squaredNorm() / 3.0;
        s_mag += (m.mag_err_nT - mag).cwiseQuotient(mag).squaredNorm() / 3.0;
        s_bdev += (m.b_dev_n_nT - bdev).cwiseQuotient(bdev).squaredNorm() / 3.0;
        if (i == 0) {
            EXPECT_NEAR(a.q_nb.norm(), 1.0, 1e-15);
            EXPECT_DOUBLE_EQ(a.att_sigma_rad, e.att_sigma_rad);
            EXPECT_TRUE(a.gyr_err_sigma_rps.isApprox(0.01 * gyr.cwiseAbs()));
            EXPECT_TRUE(a.acc_err_sigma_mps2.isApprox(0.01 * acc.cwiseAbs()));
            EXPECT_TRUE(m.mag_err_sigma_nT.isApprox(0.01 * mag.cwiseAbs()));
            EXPECT_TRUE(m.b_dev_sigma_nT.isApprox(0.10 * bdev.cwiseAbs()));
        }
    }
    // RMS from n (or 3n) chi-square samples: relative standard error <= sqrt(2/n)/2 = 1.1 %; 5 % tolerance.
    EXPECT_NEAR(std::sqrt(s_att / n) / e.att_sigma_rad, 1.0, 0.05);
    EXPECT_NEAR(std::sqrt(s_gyr / n), 0.01, 0.05 * 0.01);
    EXPECT_NEAR(std::sqrt(s_acc / n), 0.01, 0.05 * 0.01);
    EXPECT_NEAR(std::sqrt(s_mag / n), 0.01, 0.05 * 0.01);
    EXPECT_NEAR(std::sqrt(s_bdev / n), 0.10, 0.05 * 0.10);
}

TEST(Alignment, ZeroErrorsGiveTheTruthAndSameStreamSameDraws) {
    const AlignmentErrors exact{0.0, true, 0.0, 0.0, 0.0, 0.0};
    const math::Quat q = math::quat_from_euler({-2.0, 0.1, 0.2});
    rnd::Stream s(3);
    const ImuAlignment a = align_imu(exact, q, Vec3(1e-3, 2e-3, 3e-3), Vec3(0.1, 0.2, 0.3), s);
    EXPECT_LT(math::rotv_from_quat(a.q_nb * q.conjugate()).norm(), 1e-15);
    EXPECT_EQ(a.acc_err_mps2, Vec3(0.1, 0.2, 0.3));
    rnd::Stream s1(9), s2(9);
    const AlignmentErrors e;
    EXPECT_EQ(align_imu(e, q, Vec3::Ones(), Vec3::Ones(), s1).q_nb.coeffs(),
              align_imu(e, q, Vec3::Ones(), Vec3::Ones(), s2).q_nb.coeffs());
}

TEST(Alignment, SuiteSectionIsReadAndValidated) {
    const SensorSuiteParams s = load_sensor_suite(test::sensors_config_dir() / "suite.yaml");
    EXPECT_EQ(s.alignment, AlignmentErrors{});  // the suite file holds the reference values
    const auto bad = config::Config::parse(
        "att_error_sigma_deg: 0.1\nnormalise_error_axis: true\ngyr_rel_error: 2.0\nacc_rel_error: 0.01\n"
        "mag_rel_error: 0.01\nb_dev_rel_error: 0.1\n",
        "suite.yaml");
    EXPECT_THROW(AlignmentErrors::from_config(bad), config::ConfigError);
    const auto unknown = config::Config::parse(
        "att_error_sigma_deg: 0.1\nnormalise_error_axis: true\ngyr_rel_error: 0.01\nacc_rel_error: 0.01\n"
        "mag_rel_error: 0.01\nb_dev_rel_error: 0.1\nextra: 1\n",
        "suite.yaml");
    EXPECT_THROW(AlignmentErrors::from_config(unknown), config::ConfigError);
}
