// ISA / INSA atmosphere and the offsets ramp.
#include <gtest/gtest.h>

#include <cmath>

#include "atmosphere/insa.hpp"
#include "atmosphere/offsets_ramp.hpp"

using namespace gdnav;

TEST(Atmosphere, IsaMatchesPublishedTable) {
    // ICAO standard atmosphere (Doc 7488) / US Standard Atmosphere 1976, geopotential altitude:
    // H [m], T [K], p [Pa], rho [kg/m^3]
    struct Row {
        double H, T, p, rho;
    };
    const Row table[] = {{0.0, 288.15, 101325.0, 1.2250},
                         {1000.0, 281.65, 89874.6, 1.1116},
                         {2700.0, 270.60, 72824.8, 0.93754},
                         {5000.0, 255.65, 54019.9, 0.73612}};
    for (const Row& r : table) {
        const atm::AirProperties a = atm::air_properties(r.H, 0.0, 0.0);
        EXPECT_NEAR(a.Hp_m, r.H, 1e-6);
        EXPECT_NEAR(a.T_K, r.T, 0.005) << r.H;
        EXPECT_NEAR(a.p_Pa, r.p, 0.1) << r.H;
        EXPECT_NEAR(a.rho_kgpm3, r.rho, 6e-5) << r.H;
    }
    // Speed of sound at sea level 340.294 m/s.
    EXPECT_NEAR(atm::speed_of_sound_mps(288.15), 340.294, 1e-3);
}

TEST(Atmosphere, PressureAltitudeInverse) {
    for (double hp : {-500.0, 0.0, 1234.5, 2700.0, 8000.0}) {
        EXPECT_NEAR(atm::pressure_altitude_m(atm::pressure_Pa(hp)), hp, 1e-8);
        // dp/dHp against a central difference.
        const double num = (atm::pressure_Pa(hp + 0.01) - atm::pressure_Pa(hp - 0.01)) / 0.02;
        EXPECT_NEAR(atm::dp_dHp_Papm(hp), num, 1e-6 * std::abs(num));
    }
}

TEST(Atmosphere, InsaHydrostaticRelation) {
    // H(Hp) must satisfy dH/dHp = T / T_ISA and H(Hp_MSL) = 0 (independent check of the closed form).
    for (double dT : {-10.0, 0.0, 10.0}) {
        for (double dp : {-1500.0, 0.0, 1500.0}) {
            const double hp_msl = atm::pressure_altitude_msl_m(dp);
            EXPECT_NEAR(atm::geopotential_altitude_m(hp_msl, dT, dp), 0.0, 1e-9);
            EXPECT_NEAR(atm::pressure_Pa(hp_msl), atm::kP0_Pa + dp, 1e-8);
            for (double hp : {500.0, 2700.0, 4500.0}) {
                const double num = (atm::geopotential_altitude_m(hp + 0.01, dT, dp) -
                                    atm::geopotential_altitude_m(hp - 0.01, dT, dp)) /
                                   0.02;
                EXPECT_NEAR(num, atm::temperature_K(hp, dT) / atm::temperature_isa_K(hp), 1e-8);
            }
        }
    }
    // Hand value: dT = +10 K, dp = 0 at Hp = 2700 m: H = 2700 + (10 / -0.0065) ln(270.6 / 288.15) = 2796.677 m.
    EXPECT_NEAR(atm::geopotential_altitude_m(2700.0, 10.0, 0.0), 2700.0 + 10.0 / -0.0065 * std::log(270.6 / 288.15),
                1e-9);
    EXPECT_NEAR(atm::geopotential_altitude_m(2700.0, 10.0, 0.0), 2796.677, 1e-3);
}

TEST(Atmosphere, InsaRoundTrips) {
    for (double dT : {-10.0, 10.0}) {
        for (double dp : {-1500.0, 1500.0}) {
            for (double H : {0.0, 1000.0, 2700.0, 5000.0}) {
                const double hp = atm::pressure_altitude_from_geopotential_m(H, dT, dp);
                EXPECT_NEAR(atm::geopotential_altitude_m(hp, dT, dp), H, 1e-8);
                // Warm start far away converges to the same value.
                EXPECT_NEAR(atm::pressure_altitude_from_geopotential_m(H, dT, dp, H + 3000.0), hp, 1e-8);
                // Inverse helpers recover the offsets.
                const double T = atm::temperature_K(hp, dT);
                EXPECT_NEAR(atm::temperature_offset_K(T, hp), dT, 1e-12);
                EXPECT_NEAR(atm::pressure_offset_Pa(dT, hp, H), dp, 1e-6);
            }
        }
    }
    // In a warmer air column pressure decays more slowly with height, so a given geopotential altitude has a lower
    // pressure altitude: Hp(H = 2700; +10 K) < 2700 < Hp(2700; -10 K).
    EXPECT_LT(atm::pressure_altitude_from_geopotential_m(2700.0, 10.0, 0.0), 2700.0);
    EXPECT_GT(atm::pressure_altitude_from_geopotential_m(2700.0, -10.0, 0.0), 2700.0);
}

TEST(Atmosphere, PitotRoundTripAndLowSpeedLimit) {
    const double p = 72824.8, T = 270.6;
    for (double v : {5.0, 29.0, 60.0, 150.0}) {
        const double pt = atm::total_pressure_Pa(v, p, T);
        EXPECT_NEAR(atm::tas_from_total_pressure_mps(pt, p, T), v, 1e-9 * v);
    }
    // Incompressible limit: p_t - p ~ rho V^2 / 2 (1 + M^2 / 4).
    const double v = 29.0, rho = p / (atm::kR_JpkgK * T);
    const double m = v / atm::speed_of_sound_mps(T);
    EXPECT_NEAR(atm::total_pressure_Pa(v, p, T) - p, 0.5 * rho * v * v * (1.0 + m * m / 4.0), 1e-3);
}

TEST(Atmosphere, OffsetsRampProfile) {
    atm::OffsetsRampParams p;
    p.dT_ini_K = 1.0;
    p.dT_end_K = -7.0;
    p.t_ini_dT_s = 400.0;
    p.t_end_dT_s = 2000.0;
    p.dp_ini_Pa = -300.0;
    p.dp_end_Pa = -350.0;
    p.t_ini_dp_s = 800.0;
    p.t_end_dp_s = 2200.0;
    const atm::OffsetsRamp r(p);
    EXPECT_DOUBLE_EQ(r.at(0.0).dT_K, 1.0);
    EXPECT_DOUBLE_EQ(r.at(1200.0).dT_K, -3.0);
    EXPECT_DOUBLE_EQ(r.at(5000.0).dT_K, -7.0);
    EXPECT_DOUBLE_EQ(r.at(500.0).dp_Pa, -300.0);
    EXPECT_DOUBLE_EQ(r.at(1500.0).dp_Pa, -325.0);
    EXPECT_DOUBLE_EQ(r.at(2200.0).dp_Pa, -350.0);
}

TEST(Atmosphere, OffsetsDrawsFollowTheScenarioDistributions) {
    rnd::Stream s1 = rnd::Stream::derive(11, 0, "offsets");
    const int n = 8000;
    double sum_dT2 = 0.0, sum_dp2 = 0.0, sum_jT2 = 0.0, sum_jp2 = 0.0;
    for (int i = 0; i < n; ++i) {
        const atm::OffsetsRampParams p = atm::draw_offsets_scenario(s1, true);
        ASSERT_GE(p.t_ini_dT_s, 50.0);
        ASSERT_GE(p.t_ini_dp_s, 50.0);
        ASSERT_GE(p.t_end_dT_s, p.t_ini_dT_s + 600.0);
        ASSERT_GE(p.t_end_dp_s, p.t_ini_dp_s + 600.0);
        sum_dT2 += p.dT_ini_K * p.dT_ini_K;
        sum_dp2 += p.dp_ini_Pa * p.dp_ini_Pa;
        sum_jT2 += (p.dT_end_K - p.dT_ini_K) * (p.dT_end_K - p.dT_ini_K);
        sum_jp2 += (p.dp_end_Pa - p.dp_ini_Pa) * (p.dp_end_Pa - p.dp_ini_Pa);
    }
    // Relative standard error of a sample std with 8000 samples: 0.8 %; allow 4 %.
    EXPECT_NEAR(std::sqrt(sum_dT2 / n), 10.0, 0.4);
    EXPECT_NEAR(std::sqrt(sum_dp2 / n), 1500.0, 60.0);
    EXPECT_NEAR(std::sqrt(sum_jT2 / n), 3.0, 0.12);
    EXPECT_NEAR(std::sqrt(sum_jp2 / n), 300.0, 12.0);

    // Scenario 2 is constant and shares the initial offsets with scenario 1 for the same stream.
    rnd::Stream a = rnd::Stream::derive(5, 3, "offsets");
    rnd::Stream b = rnd::Stream::derive(5, 3, "offsets");
    const atm::OffsetsRampParams p1 = atm::draw_offsets_scenario(a, true);
    const atm::OffsetsRampParams p2 = atm::draw_offsets_scenario(b, false);
    EXPECT_EQ(p1.dT_ini_K, p2.dT_ini_K);
    EXPECT_EQ(p1.dp_ini_Pa, p2.dp_ini_Pa);
    EXPECT_EQ(p2.dT_end_K, p2.dT_ini_K);
    EXPECT_EQ(p2.dp_end_Pa, p2.dp_ini_Pa);
}
