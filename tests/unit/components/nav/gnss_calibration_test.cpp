// Keeping the GNSS calibration (variant keep_gnss_calibration; docs/navigation.md, "Keeping the GNSS calibration"):
// the joint GNSS/INS estimator of in_flight_aligner.hpp on synthesised flights, started from a pre-flight alignment
// drawn with the sensors' error model (B_dev known to 10 %), 120 s each. Heading: with the magnetometer left out after
// a truth-free start (heading sigma 10 deg), only GNSS can tell it; in straight level flight it does not (the sigma
// stays at its start), in 20-degree-bank turns each way it does (below 0.5 deg). B_dev: the magnetometer alone pins one combination of
// heading, E_mag and B_dev, so on a straight leg the B_dev sigma settles at the floor the start's sigmas allow within
// a minute and stays there; only the turns' GNSS heading takes it below that floor. At the hand-over the attitude
// filter starts from the estimator's joint covariance, correlations included.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "attitude_filter.hpp"
#include "in_flight_aligner.hpp"
#include "nav_synthetic.hpp"

using namespace gdnav;
using namespace gdnav::nav;

namespace {

constexpr int kBdev = 9;  // B_dev in AttitudeHandover::p_err (phi, E_gyr, E_mag, B_dev)

synth::Scenario flight(bool turning) {
    synth::Scenario sc;
    sc.yaw0_rad = 0.7;
    sc.aoa_rad = 0.0;  // the turn reversal is exact only with v_tas on the roll axis
    if (turning) {
        sc.bank_rad = math::deg2rad(20.0);
        sc.yaw_rate_rps = 9.80665 * std::tan(sc.bank_rad) / sc.tas_mps;
        sc.reverse_turn_at_s = 60.0;
    }
    sc.gyr_err_b_rps = {math::deg2rad(0.05), math::deg2rad(-0.04), math::deg2rad(0.03)};
    sc.acc_err_b_mps2 = {0.05, -0.04, 0.03};
    sc.mag_err_b_nT = {400.0, -300.0, 250.0};
    sc.b_dev_n_nT = {120.0, -80.0, 150.0};
    return sc;
}

struct Flown {
    InFlightAligner est;
    synth::Truth truth;
    double heading_sigma0_rad{0.0};
    double b_dev_sigma0_nT{0.0};
    std::string history;  // heading and horizontal B_dev sigmas every 20 s
    double b_dev_sigma_40s_nT{0.0};
};

double horizontal_b_dev_sigma_nT(const InFlightAligner& a) {
    const AttitudeHandover h = a.handover();
    return std::sqrt(std::max(h.p_err(kBdev, kBdev), h.p_err(kBdev + 1, kBdev + 1)));
}

// 120 s from the published alignment (drawn with the sensors' error model), or without the magnetometer from the
// truth-free start; the hand-over at the GNSS loss.
Flown fly(bool turning, bool magnetometer, std::uint64_t seed) {
    synth::Generator gen(flight(turning), rnd::Stream(seed));
    const Alignment published = gen.alignment(rnd::Stream(seed + 100));
    InFlightAlignerSettings settings;
    if (!magnetometer) settings.mag_period_steps = std::numeric_limits<int>::max();
    Flown f{InFlightAligner(settings, 0.01, HandOver::kAtGnssLoss), {}, 0.0, 0.0, {}, 0.0};
    for (int k = 0; k < 12000; ++k) {
        const synth::Sample s = gen.next();
        f.truth = s.truth;
        const bool was_started = f.est.started();
        EXPECT_FALSE(step_in_flight_aligner(f.est, s.truth.t_s, s.imu, s.mag, s.gnss, s.air,
                                            magnetometer ? &published : nullptr));
        if (f.est.started() && !was_started) {
            f.heading_sigma0_rad = f.est.heading_sigma_rad();
            f.b_dev_sigma0_nT = horizontal_b_dev_sigma_nT(f.est);
        }
        if (k == 3999) f.b_dev_sigma_40s_nT = horizontal_b_dev_sigma_nT(f.est);
        if (k % 2000 == 1999) {
            char row[64];
            std::snprintf(row, sizeof(row), " %3.0fs %.3f/%.0f", s.truth.t_s, math::rad2deg(f.est.heading_sigma_rad()),
                          horizontal_b_dev_sigma_nT(f.est));
            f.history += row;
        }
    }
    return f;
}

}  // namespace

TEST(NavGnssCalibration, TurnsMakeHeadingAndFieldErrorObservableAStraightLegDoesNot) {
    for (const std::uint64_t seed : {3u, 4u, 5u}) {
        const Flown straight = fly(false, true, seed), turns = fly(true, true, seed);
        const Flown straight_gnss_only = fly(false, false, seed), turns_gnss_only = fly(true, false, seed);
        for (const Flown* f : {&straight, &turns, &straight_gnss_only, &turns_gnss_only}) {
            const Vec3 e = math::rotv_from_quat(f->est.q_nb() * f->truth.q_nb.conjugate());
            std::printf("seed %llu %-8s %-21s heading sigma %.3f -> %.4f deg (error %+.4f deg), horizontal B_dev sigma "
                        "%.1f -> %.1f nT\n  every 20 s, heading sigma [deg] / B_dev sigma [nT]:%s\n",
                        static_cast<unsigned long long>(seed), f == &straight || f == &straight_gnss_only ? "straight"
                                                                                                        : "turns",
                        f == &straight || f == &turns ? "GNSS and magnetometer" : "GNSS only",
                        math::rad2deg(f->heading_sigma0_rad), math::rad2deg(f->est.heading_sigma_rad()),
                        math::rad2deg(e.z()), f->b_dev_sigma0_nT, horizontal_b_dev_sigma_nT(f->est),
                        f->history.c_str());
            EXPECT_FALSE(f->est.handed_over());  // only the GNSS loss ends it
            EXPECT_LT(std::fabs(e.z()), 3.0 * f->est.heading_sigma_rad() + math::deg2rad(0.005));
        }
        // Heading from GNSS alone: not on a straight leg, in the turns.
        EXPECT_GT(straight_gnss_only.est.heading_sigma_rad(), 0.9 * straight_gnss_only.heading_sigma0_rad);
        EXPECT_LT(turns_gnss_only.est.heading_sigma_rad(), math::deg2rad(0.5));
        // B_dev: the straight leg's floor is reached within 40 s and held; the turns go well below it.
        EXPECT_GT(horizontal_b_dev_sigma_nT(straight.est), 0.95 * straight.b_dev_sigma_40s_nT);
        EXPECT_LT(horizontal_b_dev_sigma_nT(turns.est), 0.7 * horizontal_b_dev_sigma_nT(straight.est));
        EXPECT_LT(turns.est.heading_sigma_rad(), 0.7 * straight.est.heading_sigma_rad());
    }
}

TEST(NavGnssCalibration, TheAttitudeFilterStartsFromTheJointCovariance) {
    Flown f = fly(true, true, 7);
    f.est.hand_over(120.0);
    ASSERT_TRUE(f.est.handed_over());
    const AttitudeHandover h = f.est.handover();
    for (const char* form : {"additive", "error_state"}) {
        AttitudeFilter filter;
        AttitudeFilter::Tuning t;
        t.formulation = std::string(form) == "error_state" ? AttitudeFormulation::kErrorState
                                                            : AttitudeFormulation::kAdditive;
        filter.configure(t, rnd::Stream{});
        const AttitudeEstimate e = filter.hand_over(12000, 120.0, h);
        // The attitude covariance about N is the estimator's, and the quaternion is its attitude.
        const Eigen::Matrix3d p_att = filter.attitude_covariance_n();
        const Eigen::Matrix3d p_est = h.p_err.topLeftCorner(3, 3);
        EXPECT_LT((p_att - p_est).norm(), 1e-6 * p_est.norm()) << form;
        EXPECT_NEAR(e.att_sigma_rad.z(), f.est.heading_sigma_rad(), 1e-6 * f.est.heading_sigma_rad()) << form;
        EXPECT_LT(math::rotv_from_quat(e.q_nb * h.q_nb.conjugate()).norm(), 1e-12) << form;
        EXPECT_EQ(e.b_dev_n_nT, h.b_dev_n_nT);
        // The correlation of heading and B_dev survives the hand-over (additive: through the quaternion block).
        if (t.formulation == AttitudeFormulation::kErrorState) {
            const double c_in = h.p_err(2, kBdev);
            const double c_out = filter.error_covariance()(2, eskf::kBdev);
            EXPECT_NEAR(c_out, c_in, 1e-6 * std::fabs(c_in) + 1e-15) << form;
        }
    }
}

// Through the loss (variant keep_gnss_calibration, HandOver::kNever): 120 s of turns with GNSS, then 240 s more of
// the same turns without it. The estimator goes on with the air data (ground velocity = air velocity + a walking wind)
// and the magnetometer: its heading sigma stays near what the turns gave it, and its errors stay within their sigmas.
// The synthetic magnetometer has no scale, cross-coupling or soft-iron error, so the estimator is told so (a prior
// of zero on M); with the baseline magnetometer's prior the heading after the loss is only as good as the turns
// taught M (docs/navigation.md, "Keeping the GNSS calibration").
TEST(NavGnssCalibration, ThroughTheLossTheAirDataAndTheMagnetometerKeepTheHeading) {
    InFlightAlignerSettings settings;
    settings.mag_scale_sigma = settings.mag_cross_sigma = 0.0;
    for (const std::uint64_t seed : {3u, 4u, 5u}) {
        synth::Generator gen(flight(true), rnd::Stream(seed));
        const Alignment published = gen.alignment(rnd::Stream(seed + 100));
        InFlightAligner est(settings, 0.01, HandOver::kNever);
        double heading_sigma_loss_rad = 0.0, tilt_sigma_loss_rad = 0.0, heading_sigma_120s_rad = 0.0;
        synth::Truth truth;
        for (int k = 0; k < 36000; ++k) {
            synth::Sample s = gen.next();
            truth = s.truth;
            if (k >= 12000) s.gnss.fix_valid = false;
            EXPECT_FALSE(step_in_flight_aligner(est, s.truth.t_s, s.imu, s.mag, s.gnss, s.air, &published));
            if (k == 12000) {
                est.hand_over(s.truth.t_s);
                heading_sigma_loss_rad = est.heading_sigma_rad();
                tilt_sigma_loss_rad = est.tilt_sigma_rad();
            }
            if (k == 24000) heading_sigma_120s_rad = est.heading_sigma_rad();
        }
        const Vec3 e = math::rotv_from_quat(est.q_nb() * truth.q_nb.conjugate());
        std::printf("seed %llu: at the loss heading sigma %.4f deg, tilt sigma %.4f deg; 120 s later heading sigma "
                    "%.4f deg; 240 s later %.4f / %.4f deg, error heading %+.4f deg, tilt %.4f deg\n",
                    static_cast<unsigned long long>(seed), math::rad2deg(heading_sigma_loss_rad),
                    math::rad2deg(tilt_sigma_loss_rad), math::rad2deg(heading_sigma_120s_rad),
                    math::rad2deg(est.heading_sigma_rad()),
                    math::rad2deg(est.tilt_sigma_rad()), math::rad2deg(e.z()),
                    math::rad2deg(std::hypot(e.x(), e.y())));
        EXPECT_TRUE(est.handed_over());
        EXPECT_TRUE(est.running());  // it goes on after the loss
        EXPECT_LT(est.heading_sigma_rad(), 1.1 * heading_sigma_120s_rad);  // settled, not drifting away
        EXPECT_LT(std::fabs(e.z()), 3.0 * est.heading_sigma_rad() + math::deg2rad(0.005));
        EXPECT_LT(std::hypot(e.x(), e.y()), 3.0 * est.tilt_sigma_rad() + math::deg2rad(0.005));
    }
}

// The air-data offsets (HandOver::kNever): the estimator splits the air velocity's error from the wind only when the
// aircraft turns, as the wind stays put in NED while an offset of the airspeed or the sideslip turns with the body.
// 120 s with GNSS and air data carrying a TAS offset of 0.4 m/s and an AOS offset of 0.3 deg: in the turns the TAS
// sigma falls below a third of its prior and the AOS sigma below 60 % of its (a sideslip offset turns the air velocity
// as a heading error does, so it is only as well known as the heading), the estimates within 3 sigma of the offsets;
// on a straight leg neither sigma falls below 80 % of its prior (what the GNSS sees there is one sum of wind and
// offset).
TEST(NavGnssCalibration, TurnsMakeTheAirDataOffsetsObservableAStraightLegDoesNot) {
    const InFlightAlignerSettings settings;
    const double tas_offset_mps = 0.4, aos_offset_rad = math::deg2rad(0.3);
    for (const bool turning : {false, true}) {
        for (const std::uint64_t seed : {3u, 4u}) {
            synth::Generator gen(flight(turning), rnd::Stream(seed));
            const Alignment published = gen.alignment(rnd::Stream(seed + 100));
            InFlightAligner est(settings, 0.01, HandOver::kNever);
            for (int k = 0; k < 12000; ++k) {
                synth::Sample s = gen.next();
                s.air.tas_mps += tas_offset_mps;
                s.air.aos_rad += aos_offset_rad;
                EXPECT_FALSE(step_in_flight_aligner(est, s.truth.t_s, s.imu, s.mag, s.gnss, s.air, &published));
            }
            const Vec3 sig = est.air_offsets_sigma();
            const Vec3 b = est.air_offsets();
            std::printf("%s, seed %llu: TAS offset %.3f +- %.3f m/s (true %.3f), AOS offset %.3f +- %.3f deg (true "
                        "%.3f)\n",
                        turning ? "turns" : "straight", static_cast<unsigned long long>(seed), b.x(), sig.x(),
                        tas_offset_mps, math::rad2deg(b.z()), math::rad2deg(sig.z()), math::rad2deg(aos_offset_rad));
            if (turning) {
                EXPECT_LT(sig.x(), settings.tas_offset_sigma_mps / 3.0);
                EXPECT_LT(sig.z(), 0.6 * settings.aos_offset_sigma_rad);
                EXPECT_LT(std::fabs(b.x() - tas_offset_mps), 3.0 * sig.x());
                EXPECT_LT(std::fabs(b.z() - aos_offset_rad), 3.0 * sig.z());
            } else {
                EXPECT_GT(sig.x(), 0.8 * settings.tas_offset_sigma_mps);
                EXPECT_GT(sig.z(), 0.8 * settings.aos_offset_sigma_rad);
            }
        }
    }
}
