// The in-flight alignment monitor (alignment_monitor.hpp) on the real filters' outputs over synthetic flights: it must
// not declare a straight and level flight aligned while a 1 deg tilt error hides behind an unknown accelerometer bias,
// and must declare a turning flight aligned.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "alignment_monitor.hpp"
#include "nav_chain.hpp"

using namespace gdnav;
using namespace gdnav::nav;

namespace {

constexpr double kG = 9.80665;

struct MonitorRun {
    test::ChainRun chain;
    std::vector<bool> aligned;
    std::vector<double> tilt_sigma_rad;
    double t_aligned_s{-1.0};
};

// Truth-free chain (init.mode measurements) with the accelerometer bias `acc_err` and the monitor fed per step as
// nav_pos feeds it.
MonitorRun run_monitored(const synth::Scenario& sc, const Vec3& acc_err, int steps) {
    synth::Scenario s = sc;
    s.acc_err_b_mps2 = acc_err;
    test::ChainOptions o;
    o.reference_init = false;
    o.steps = steps;
    std::vector<std::optional<double>> d2(static_cast<std::size_t>(steps) + 1);
    std::vector<bool> denied(d2.size(), false);
    double acc_sigma0 = 0.0;
    std::uint64_t accepted = 0;
    o.inspect = [&](int k, const PositionFilter& pos) {
        if (k == 0) acc_sigma0 = std::sqrt(pos.aided_covariance()(aided::kE, aided::kE));
        if (pos.gate_accepted() > accepted) d2[static_cast<std::size_t>(k)] = pos.gate_d2_last();
        accepted = pos.gate_accepted();
        denied[static_cast<std::size_t>(k)] = pos.gnss_denied();
    };
    MonitorRun r;
    r.chain = test::run_chain(s, o, 91);
    AlignmentMonitor m(AlignmentCriteria{}, sc.dt_s);
    const auto& att0 = r.chain.att.front();
    m.start(std::max(att0.att_sigma_rad.x(), att0.att_sigma_rad.y()), acc_sigma0);
    for (std::size_t k = 1; k < d2.size(); ++k) {
        const auto& a = r.chain.att[k];
        m.step(r.chain.data[k].truth.t_s, r.chain.data[k].imu.f_b_mps2, a.q_nb, a.att_sigma_rad.z(),
               d2[k] ? &*d2[k] : nullptr, denied[k]);
        r.aligned.push_back(m.aligned());
        r.tilt_sigma_rad.push_back(m.tilt_sigma_rad());
    }
    if (m.aligned()) r.t_aligned_s = m.t_aligned_s();
    return r;
}

synth::Scenario level_turn(double bank_deg) {
    synth::Scenario sc;
    sc.bank_rad = math::deg2rad(bank_deg);
    sc.yaw_rate_rps = kG * std::tan(sc.bank_rad) / sc.tas_mps;  // coordinated
    return sc;
}

}  // namespace

TEST(NavAlignmentMonitor, NotAlignedOnStraightLevelFlightWithATiltErrorHiddenByTheAccelerometerBias) {
    // An x bias of g sin(1 deg) levels the truth-free start 1 deg off in pitch, and straight flight cannot tell it
    // from a tilt: the filters keep the 1 deg error while their own covariances shrink.
    const Vec3 bias(kG * std::sin(math::deg2rad(1.0)), 0.0, 0.0);
    const MonitorRun r = run_monitored(level_turn(0.0), bias, 30000);
    const double err_end = math::rad2deg(test::att_error(r.chain, r.chain.att.size() - 1));
    const double filter_sigma = math::rad2deg(r.chain.att.back().att_sigma_rad.head<2>().maxCoeff());
    std::printf("straight: attitude error at 300 s %.3f deg, filter tilt sigma %.3f deg, monitor tilt sigma %.3f deg\n",
                err_end, filter_sigma, math::rad2deg(r.tilt_sigma_rad.back()));
    EXPECT_GT(err_end, 0.5);                        // the injected error is there ...
    EXPECT_LT(filter_sigma, 0.3);                    // ... hidden from the attitude filter's own covariance
    for (bool a : r.aligned) ASSERT_FALSE(a);        // ... but not from the monitor
    EXPECT_GT(math::rad2deg(r.tilt_sigma_rad.back()), 0.5);
}

TEST(NavAlignmentMonitor, AlignedDuringATurn) {
    const Vec3 bias(kG * std::sin(math::deg2rad(1.0)), 0.0, 0.0);
    const MonitorRun r = run_monitored(level_turn(20.0), bias, 30000);
    const double turn_s = 2.0 * math::kPi / level_turn(20.0).yaw_rate_rps;
    std::printf("turn at 20 deg bank (%.1f s per turn): aligned at %.2f s, monitor tilt sigma %.3f deg, attitude error "
                "then %.3f deg, at 300 s %.3f deg\n",
                turn_s, r.t_aligned_s, math::rad2deg(r.tilt_sigma_rad.back()),
                r.t_aligned_s > 0 ? math::rad2deg(test::att_error(r.chain, static_cast<std::size_t>(r.t_aligned_s / 0.01)))
                                  : -1.0,
                math::rad2deg(test::att_error(r.chain, r.chain.att.size() - 1)));
    ASSERT_GT(r.t_aligned_s, 0.0);
    EXPECT_LT(r.t_aligned_s, 2.0 * turn_s);
}

TEST(NavAlignmentMonitor, NeverAlignedWithInconsistentInnovationsOrWithoutGnss) {
    AlignmentCriteria c;
    c.hold_s = 1.0;
    const synth::Scenario sc = level_turn(20.0);
    for (int mode = 0; mode < 2; ++mode) {
        AlignmentMonitor m(c, 0.01);
        m.start(math::deg2rad(5.0), 0.157);
        synth::Generator gen(sc, rnd::Stream(5));
        for (int k = 0; k < 20000; ++k) {
            const synth::Sample s = gen.next();
            const double d2 = 30.0;  // a filter whose GNSS innovations are 5 times too large
            const double d2_ok = 6.0;
            m.step(s.truth.t_s, s.imu.f_b_mps2, s.truth.q_nb, 1e-3, k % 100 == 0 ? (mode == 0 ? &d2 : &d2_ok) : nullptr,
                   mode == 1);
        }
        EXPECT_FALSE(m.aligned()) << mode;
    }
}

TEST(NavAlignmentMonitor, BadKeysNameTheKey) {
    const auto bad = [](const char* text) {
        try {
            (void)parse_alignment_criteria(config::Config::parse(text, "nav_pos.alignment_check"));
        } catch (const config::ConfigError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(bad("{tilt_sigma_max_deg: 20}").find("tilt_sigma_max_deg"), std::string::npos);
    EXPECT_NE(bad("{hold: 3}").find("hold"), std::string::npos);
    EXPECT_EQ(bad("{}"), "");
}
