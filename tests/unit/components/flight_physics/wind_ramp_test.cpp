// Wind ramp: profile, "towards" convention and the scenario draws.
#include "flight_physics/model/wind_ramp.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace gdnav;
using physics::WindRamp;
using physics::WindRampParams;

TEST(WindRamp, InterpolatesNorthAndEastComponents) {
    WindRampParams p;
    p.t_ini_s = 100.0;
    p.t_end_s = 300.0;
    p.speed_ini_mps = 4.0;
    p.bearing_ini_rad = math::deg2rad(90.0);  // air moves towards the east
    p.speed_end_mps = 6.0;
    p.bearing_end_rad = 0.0;  // towards the north
    const WindRamp w(p);
    EXPECT_NEAR(w.wind_n_mps(0.0).x(), 0.0, 1e-12);
    EXPECT_NEAR(w.wind_n_mps(0.0).y(), 4.0, 1e-12);
    EXPECT_EQ(w.wind_n_mps(0.0).z(), 0.0);
    // Midway: components average ((0 + 6) / 2, (4 + 0) / 2), not speed and bearing.
    EXPECT_NEAR(w.wind_n_mps(200.0).x(), 3.0, 1e-12);
    EXPECT_NEAR(w.wind_n_mps(200.0).y(), 2.0, 1e-12);
    EXPECT_NEAR(w.wind_n_mps(1e4).x(), 6.0, 1e-12);
    EXPECT_NEAR(w.wind_n_mps(1e4).y(), 0.0, 1e-12);
}

TEST(WindRamp, ScenarioDrawsFollowTheSpecification) {
    rnd::Stream s = rnd::Stream::derive(3, 0, "wind");
    const int n = 40000;
    double sum_v2 = 0.0, sum_dv2 = 0.0, sum_dchi2 = 0.0;
    int n_small = 0;
    for (int i = 0; i < n; ++i) {
        const WindRampParams p = physics::draw_wind_scenario(s, true);
        ASSERT_GE(p.t_ini_s, 50.0);
        ASSERT_GE(p.t_end_s, p.t_ini_s + 300.0);
        ASSERT_GE(p.speed_ini_mps, 0.0);
        ASSERT_GE(p.speed_end_mps, 0.0);
        const double b = math::rad2deg(p.bearing_ini_rad);
        ASSERT_NEAR(b, std::round(b), 1e-9);
        ASSERT_GT(b, -180.0);
        ASSERT_LE(b, 180.0 + 1e-9);
        sum_v2 += p.speed_ini_mps * p.speed_ini_mps;  // half-normal: E[V^2] = 49
        if (p.speed_ini_mps > 12.0) {                 // 4 sigma from the sign flip: the jumps are plain normals
            sum_dv2 += (p.speed_end_mps - p.speed_ini_mps) * (p.speed_end_mps - p.speed_ini_mps);
            const double dchi = math::wrap_pi(p.bearing_end_rad - p.bearing_ini_rad);
            sum_dchi2 += dchi * dchi;
            ++n_small;
        }
    }
    EXPECT_NEAR(std::sqrt(sum_v2 / n), 7.0, 0.3);
    EXPECT_NEAR(std::sqrt(sum_dv2 / n_small), 3.0, 0.15);
    EXPECT_NEAR(std::sqrt(sum_dchi2 / n_small), math::deg2rad(15.0), math::deg2rad(0.75));

    // Scenario 2: constant wind equal to scenario 1's initial wind for the same stream.
    rnd::Stream a = rnd::Stream::derive(9, 4, "wind"), b = rnd::Stream::derive(9, 4, "wind");
    const WindRampParams p1 = physics::draw_wind_scenario(a, true);
    const WindRampParams p2 = physics::draw_wind_scenario(b, false);
    EXPECT_EQ(p1.speed_ini_mps, p2.speed_ini_mps);
    EXPECT_EQ(p1.bearing_ini_rad, p2.bearing_ini_rad);
    const WindRamp w2(p2);
    EXPECT_LT((w2.wind_n_mps(0.0) - w2.wind_n_mps(5000.0)).norm(), 1e-12);
}
