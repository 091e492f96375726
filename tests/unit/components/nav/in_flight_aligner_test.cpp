// The in-flight fine alignment (in_flight_aligner.hpp) on synthesised flights with constant sensor errors: in a
// 20-degree-bank turn each way it finds the heading, the tilt and the sensor errors from a truth-free start, within its
// own sigmas, and hands over; in one steady turn or in straight flight the heading stays uncertain (see scenario()),
// so it never hands over.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>

#include "in_flight_aligner.hpp"
#include "nav_synthetic.hpp"

using namespace gdnav;
using namespace gdnav::nav;

namespace {

struct Flown {
    InFlightAligner aligner;
    synth::Truth truth;
    double t_handed_over_s{-1.0};
};

synth::Scenario scenario(double yaw0_rad, double bank_deg) {
    synth::Scenario sc;
    sc.yaw0_rad = yaw0_rad;
    sc.bank_rad = math::deg2rad(bank_deg);
    sc.yaw_rate_rps = 9.80665 * std::tan(sc.bank_rad) / sc.tas_mps;
    // One turn each way: in a steady turn an accelerometer bias along the roll axis and a heading error give the
    // same NED acceleration error (both along the velocity, rotating with it); reversing the turn flips one of them.
    sc.aoa_rad = 0.0;
    sc.reverse_turn_at_s = 60.0;
    sc.gyr_err_b_rps = {math::deg2rad(0.15), math::deg2rad(-0.2), math::deg2rad(0.1)};
    sc.acc_err_b_mps2 = {0.12, -0.15, 0.1};
    sc.mag_err_b_nT = {400.0, -300.0, 250.0};
    sc.b_dev_n_nT = {120.0, -80.0, 150.0};
    return sc;
}

Flown fly(const synth::Scenario& sc, int steps, std::uint64_t seed,
          const InFlightAlignerSettings& settings = InFlightAlignerSettings{}) {
    synth::Generator gen(sc, rnd::Stream(seed));
    Flown f{InFlightAligner(settings, sc.dt_s), {}, -1.0};
    for (int k = 0; k < steps; ++k) {
        const synth::Sample s = gen.next();
        f.truth = s.truth;
        if (!f.aligner.started()) {
            if (s.gnss.fix_valid) f.aligner.start(s.truth.t_s, s.imu, s.mag, s.gnss, s.air);
            continue;
        }
        if (f.aligner.step(s.truth.t_s, s.imu, s.mag, s.gnss.fix_valid ? &s.gnss : nullptr)) {
            f.t_handed_over_s = s.truth.t_s;
            break;  // judged at the hand-over
        }
    }
    return f;
}

// NED-side attitude error of the estimate, rad.
Vec3 attitude_error(const Quat& q_hat, const Quat& q_true) { return math::rotv_from_quat(q_hat * q_true.conjugate()); }

}  // namespace

TEST(NavInFlightAligner, FindsHeadingTiltAndSensorErrorsInATurnFromAnyHeading) {
    for (int i = 0; i < 6; ++i) {
        const double yaw0 = math::deg2rad(-170.0 + 60.0 * i);
        const synth::Scenario sc = scenario(yaw0, 20.0);
        const Flown f = fly(sc, 15000, 21 + i);  // 60 s one way (1.1 turns), up to 90 s the other
        const InFlightAligner& a = f.aligner;
        const Vec3 e = attitude_error(a.q_nb(), f.truth.q_nb);
        const Alignment al = a.alignment();
        std::printf("heading0 %+6.1f deg: handed over at %.1f s; tilt error %+.3f %+.3f deg, heading error %+.3f deg "
                    "(sigma %.3f); gyro bias z error %+.5f deg/s, acc bias x error %+.4f m/s2\n",
                    math::rad2deg(yaw0), f.t_handed_over_s, math::rad2deg(e.x()), math::rad2deg(e.y()),
                    math::rad2deg(e.z()), math::rad2deg(a.heading_sigma_rad()),
                    math::rad2deg(al.gyr_err_rps.z() - sc.gyr_err_b_rps.z()),
                    al.acc_err_mps2.x() - sc.acc_err_b_mps2.x());
        EXPECT_TRUE(a.handed_over());
        EXPECT_LT(std::fabs(e.z()), 3.0 * a.heading_sigma_rad() + math::deg2rad(0.02));
        EXPECT_LT(std::fabs(e.x()), 3.0 * a.tilt_sigma_rad() + math::deg2rad(0.02));
        EXPECT_LT(std::fabs(e.y()), 3.0 * a.tilt_sigma_rad() + math::deg2rad(0.02));
        for (int j = 0; j < 3; ++j) {
            EXPECT_LT(std::fabs(al.gyr_err_rps[j] - sc.gyr_err_b_rps[j]), 3.0 * al.gyr_err_sigma_rps[j] + 1e-5) << j;
            EXPECT_LT(std::fabs(al.acc_err_mps2[j] - sc.acc_err_b_mps2[j]), 3.0 * al.acc_err_sigma_mps2[j] + 1e-3) << j;
        }
        EXPECT_LT(math::rad2deg(a.heading_sigma_rad()), 0.15);
    }
}

// The start's one-sample levelling reads the accelerometer bias (0.12, -0.15 m/s^2) as a tilt error of about 1.1 deg,
// which straight flight cannot tell from the bias: the hand-over must not happen there.
TEST(NavInFlightAligner, NeverHandsOverInStraightFlightOrInOneSteadyTurn) {
    for (const double bank_deg : {0.0, 20.0}) {
        synth::Scenario sc = scenario(0.5, bank_deg);
        sc.reverse_turn_at_s = std::numeric_limits<double>::infinity();
        const Flown f = fly(sc, 15000, 5);
        std::printf("bank %.0f deg, never reversed: heading sigma %.3f deg, tilt sigma %.4f deg\n", bank_deg,
                    math::rad2deg(f.aligner.heading_sigma_rad()), math::rad2deg(f.aligner.tilt_sigma_rad()));
        EXPECT_FALSE(f.aligner.handed_over());
        EXPECT_GT(math::rad2deg(f.aligner.heading_sigma_rad()), 0.5);
    }
}

TEST(NavInFlightAligner, HandsOverAtTheFirstFixFromNotBeforeOnceAligned) {
    InFlightAlignerSettings st;
    st.heading_sigma_max_rad = math::deg2rad(0.08);
    const Flown early = fly(scenario(0.3, 20.0), 15000, 8, st);
    st.not_before_s = 130.0;
    const Flown late = fly(scenario(0.3, 20.0), 15000, 8, st);
    std::printf("hand-over at %.1f s, with not_before_s 130 at %.1f s\n", early.t_handed_over_s, late.t_handed_over_s);
    ASSERT_TRUE(early.aligner.handed_over());
    EXPECT_LT(early.t_handed_over_s, 130.0);
    ASSERT_TRUE(late.aligner.handed_over());
    EXPECT_EQ(late.t_handed_over_s, 130.0);  // a fix every second, aligned long before
}

TEST(NavInFlightAligner, BadKeysNameTheKey) {
    const auto bad = [](const char* text) {
        try {
            (void)parse_in_flight_alignment(config::Config::parse(text, "nav_att.in_flight_alignment"));
        } catch (const config::ConfigError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(bad("{heading_sigma_max_deg: 50}").find("heading_sigma_max_deg"), std::string::npos);
    EXPECT_NE(bad("{hold: 3}").find("hold"), std::string::npos);
    EXPECT_EQ(bad("{}"), "");
}
