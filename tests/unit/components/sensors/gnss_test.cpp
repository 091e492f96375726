// GNSS receiver: fix schedule on the integer step index, signal loss, error statistics (position errors
// recovered independently from the output geodetic coordinates with GeographicLib), ionospheric interpolation.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <GeographicLib/LocalCartesian.hpp>

#include "sensor_test_support.hpp"
#include "sensors/model/gnss.hpp"

namespace gdnav::sensors {
namespace {

using test::rms;

GnssTruth truth_at(double lon_deg = 270.0) {
    GnssTruth t;
    t.lon_rad = math::deg2rad(lon_deg);
    t.lat_rad = math::deg2rad(45.0);
    t.h_m = 3000.0;
    t.v_n_mps = {20.0, -5.0, 0.5};
    return t;
}

// NED error of a fix, computed from the output coordinates (independent of the model's internal vector).
Vec3 ned_error(const GnssTruth& t, const GnssMeasurement& m) {
    const GeographicLib::LocalCartesian enu(math::rad2deg(t.lat_rad), math::rad2deg(t.lon_rad), t.h_m);
    double e = 0.0, n = 0.0, u = 0.0;
    enu.Forward(math::rad2deg(m.lat_rad), math::rad2deg(m.lon_rad), m.h_m, e, n, u);
    return {n, e, -u};
}

TEST(Gnss, FixesExactlyAtOneHertzAndNoneAfterLoss) {
    GnssParams p = test::baseline_suite().gnss;  // t0 = -50 s, dt = 0.01 s, t_GNSS = 100 s
    ASSERT_TRUE(p.loss_time_s.has_value());
    GnssReceiver rx;
    rx.configure(p, rnd::Stream(1));
    const GnssTruth t = truth_at();
    int fixes = 0;
    GnssMeasurement last_fix;
    for (std::uint64_t k = 0; k <= 20000; ++k) {
        const double t_s = p.t0_s + static_cast<double>(k) * p.dt_s;
        const GnssMeasurement m = rx.measure(k, t_s, t);
        const bool expect_fix = (k % 100 == 0) && k <= 15000;  // t = -50, -49, ..., 100 s
        ASSERT_EQ(m.fix_valid, expect_fix) << "k = " << k;
        EXPECT_EQ(m.step, k);
        if (m.fix_valid) {
            ++fixes;
            last_fix = m;
        } else if (fixes > 0) {
            // Between fixes and after the loss: the last fix is held unchanged.
            EXPECT_EQ(m.lat_rad, last_fix.lat_rad);
            EXPECT_EQ(m.h_m, last_fix.h_m);
            EXPECT_EQ(m.v_n_mps, last_fix.v_n_mps);
        }
    }
    EXPECT_EQ(fixes, 151);  // reference section 8: 151 fixes for t0 = -50 s, t_GNSS = 100 s
    EXPECT_EQ(last_fix.step, 15000u);
}

TEST(Gnss, LossTimeNotRepresentableInBinaryStillHitsItsStep) {
    // t0 = 0.07, t_GNSS = 3.07: (3.07 - 0.07) / 0.01 evaluates to 299.99999999999994 in doubles; a plain floor
    // would drop the fix at k = 300 (t = 3.07 s exactly on the step grid).
    GnssParams p = test::baseline_suite().gnss;
    p.t0_s = 0.07;
    p.loss_time_s = 3.07;
    GnssReceiver rx;
    rx.configure(p, rnd::Stream(2));
    ASSERT_TRUE(rx.last_fix_step().has_value());
    EXPECT_EQ(*rx.last_fix_step(), 300u);
    EXPECT_TRUE(rx.is_fix_epoch(300));
    EXPECT_FALSE(rx.is_fix_epoch(400));
    EXPECT_FALSE(rx.is_fix_epoch(250));
}

TEST(Gnss, NoLossTimeMeansAlwaysAvailableAndEarlyLossMeansNone) {
    GnssParams p = test::baseline_suite().gnss;
    p.loss_time_s.reset();
    GnssReceiver always;
    always.configure(p, rnd::Stream(3));
    EXPECT_TRUE(always.is_fix_epoch(100000000));
    p.loss_time_s = p.t0_s - 1.0;
    GnssReceiver never;
    never.configure(p, rnd::Stream(3));
    EXPECT_FALSE(never.is_fix_epoch(0));
    EXPECT_FALSE(never.measure(0, p.t0_s, truth_at()).fix_valid);
}

TEST(Gnss, WhiteErrorSigmasFromFixDifferences) {
    // Differences of consecutive fixes cancel the slow ionospheric term (it changes by ~0.16/60 m per fix:
    // variance 7e-6 m^2 against 2 * 2.12^2 = 9 m^2), so var(e_{j+1} - e_j) = 2 sigma^2. Non-overlapping pairs
    // are independent: 40 runs x 500 pairs = 20000 per axis -> s.e. of sigma 0.5 % (N and E pooled: 0.35 %).
    // Tolerance 5 %.
    GnssParams p = test::baseline_suite().gnss;
    p.loss_time_s.reset();
    const GnssTruth t = truth_at();
    std::vector<double> dh, dv, ev;
    for (int run = 0; run < 40; ++run) {
        GnssReceiver rx;
        rx.configure(p, rnd::Stream::derive(5, static_cast<std::uint64_t>(run), "sensors_gnss"));
        for (std::uint64_t j = 0; j < 1000; j += 2) {
            const GnssMeasurement a = rx.measure(j * 100, 0.0, t);
            const GnssMeasurement b = rx.measure((j + 1) * 100, 0.0, t);
            ASSERT_TRUE(a.fix_valid && b.fix_valid);
            const Vec3 d = (ned_error(t, b) - ned_error(t, a)) / std::sqrt(2.0);
            dh.push_back(d.x());
            dh.push_back(d.y());
            dv.push_back(d.z());
            for (int i = 0; i < 3; ++i) ev.push_back(a.v_n_mps[i] - t.v_n_mps[i]);
        }
    }
    RecordProperty("white_hor_m", std::to_string(rms(dh)));
    RecordProperty("white_ver_m", std::to_string(rms(dv)));
    RecordProperty("vel_mps", std::to_string(rms(ev)));
    EXPECT_NEAR(rms(dh) / 2.12, 1.0, 0.05);
    EXPECT_NEAR(rms(dv) / 4.25, 1.0, 0.05);
    EXPECT_NEAR(rms(ev) / 0.0741, 1.0, 0.05);  // n = 60000: s.e. 0.3 %
}

TEST(Gnss, TotalErrorAtFirstFixIncludesIonosphericState) {
    // First fix of a run: white error plus 0.16 m x 50 N(0,1) = 8 m ionospheric error per axis, so
    // sigma_N,E = sqrt(2.12^2 + 8^2) = 8.276 m and sigma_D = sqrt(4.25^2 + 8^2) = 9.059 m (reference 1.6).
    // n = 4000 runs: s.e. 1.1 % (vertical), 0.8 % (N, E pooled). Tolerance 5 %.
    const GnssParams p = test::baseline_suite().gnss;
    const GnssTruth t = truth_at();
    std::vector<double> eh, ev;
    for (int run = 0; run < 4000; ++run) {
        GnssReceiver rx;
        rx.configure(p, rnd::Stream::derive(6, static_cast<std::uint64_t>(run), "sensors_gnss"));
        const GnssMeasurement m = rx.measure(0, p.t0_s, t);
        const Vec3 e = ned_error(t, m);
        EXPECT_NEAR((e - m.pos_err_n_m).norm(), 0.0, 1e-6);
        eh.push_back(e.x());
        eh.push_back(e.y());
        ev.push_back(e.z());
    }
    RecordProperty("first_fix_hor_m", std::to_string(rms(eh)));
    RecordProperty("first_fix_ver_m", std::to_string(rms(ev)));
    EXPECT_NEAR(rms(eh) / std::hypot(2.12, 8.0), 1.0, 0.05);
    EXPECT_NEAR(rms(ev) / std::hypot(4.25, 8.0), 1.0, 0.05);
}

TEST(Gnss, IonosphereIsLinearBetweenNodesWithOneStepPerNode) {
    // Within a 60-fix block the ionospheric error is a straight line (second differences vanish) that moves at
    // every fix; from node to node it moves by sigma_iono (0.16 m) N(0,1) plus the band pull (which only acts
    // beyond 80 steps and adds < 1 % to the spread). 300 runs x 60 node steps x 3 axes = 54000: s.e. 0.3 %.
    GnssParams p = test::baseline_suite().gnss;
    p.loss_time_s.reset();
    const GnssTruth t = truth_at();
    std::vector<double> node_steps;
    for (int run = 0; run < 300; ++run) {
        GnssReceiver rx;
        rx.configure(p, rnd::Stream::derive(7, static_cast<std::uint64_t>(run), "sensors_gnss"));
        if (run == 0) {  // every fix of the first two blocks
            std::vector<Vec3> io;
            for (std::uint64_t j = 0; j < 120; ++j) {
                const GnssMeasurement m = rx.measure(j * 100, 0.0, t);
                ASSERT_TRUE(m.fix_valid);
                io.push_back(m.iono_err_n_m);
            }
            for (std::size_t j = 1; j + 1 < io.size(); ++j) {
                if (j % 60 == 0) continue;  // a node: the slope may change there
                EXPECT_NEAR((io[j + 1] - 2.0 * io[j] + io[j - 1]).norm(), 0.0, 1e-12) << "fix " << j;
                EXPECT_GT((io[j + 1] - io[j]).norm(), 0.0) << "piecewise constant at fix " << j;
            }
            continue;
        }
        Vec3 prev = rx.measure(0, 0.0, t).iono_err_n_m;
        for (std::uint64_t b = 1; b <= 60; ++b) {  // only node fixes: j = 60 b
            const GnssMeasurement m = rx.measure(b * 6000, 0.0, t);
            ASSERT_TRUE(m.fix_valid);
            const Vec3 cur = m.iono_err_n_m;
            for (int i = 0; i < 3; ++i) node_steps.push_back(cur[i] - prev[i]);
            prev = cur;
        }
    }
    RecordProperty("iono_node_step_m", std::to_string(rms(node_steps)));
    EXPECT_NEAR(rms(node_steps) / 0.16, 1.0, 0.05);
}

TEST(Gnss, KeepsTheLongitudeBranchOfTheTruth) {
    const GnssParams p = test::baseline_suite().gnss;
    GnssReceiver rx;
    rx.configure(p, rnd::Stream(9));
    const GnssMeasurement m = rx.measure(0, p.t0_s, truth_at(270.0));
    EXPECT_NEAR(m.lon_rad, math::deg2rad(270.0), 1e-4);  // 1e-4 rad ~ 450 m at 45 deg N
}

}  // namespace
}  // namespace gdnav::sensors
