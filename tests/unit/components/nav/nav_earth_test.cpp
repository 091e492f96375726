// Onboard Earth/atmosphere math (nav_earth.hpp) and the GNSS-denied velocity and altitude equations, against
// published tables, GeographicLib and hand computations.
#include <gtest/gtest.h>

#include <GeographicLib/Ellipsoid.hpp>
#include <GeographicLib/NormalGravity.hpp>

#include "denied_rules.hpp"
#include "math/rotation.hpp"
#include "nav_earth.hpp"
#include "nav_synthetic.hpp"

using namespace gdnav;
using namespace gdnav::nav;

TEST(NavEarth, IsaPressureMatchesIcaoTable) {
    // ICAO standard atmosphere (geopotential altitude): 1000 m 89874.6 Pa, 3000 m 70108.5 Pa, 5000 m 54019.9 Pa,
    // 11000 m 22632.1 Pa.
    EXPECT_NEAR(nav::earth::pressure_from_Hp(0.0), 101325.0, 1e-9);
    EXPECT_NEAR(nav::earth::pressure_from_Hp(1000.0), 89874.6, 0.1);
    EXPECT_NEAR(nav::earth::pressure_from_Hp(3000.0), 70108.5, 0.1);
    EXPECT_NEAR(nav::earth::pressure_from_Hp(5000.0), 54019.9, 0.1);
    EXPECT_NEAR(nav::earth::pressure_from_Hp(11000.0), 22632.1, 0.1);
    for (double hp : {-300.0, 0.0, 2700.0, 9000.0}) EXPECT_NEAR(nav::earth::Hp_from_pressure(nav::earth::pressure_from_Hp(hp)), hp, 1e-8);
}

TEST(NavEarth, InsaAltitudeChainHandCases) {
    // A: dT = 0, dp = 0  => H = Hp;  h = R_E H/(R_E - H) = 3000 * 6356766/6353766 = 3001.41648 m.
    EXPECT_NEAR(denied::altitude_from_pressure(3000.0, 0.0, 0.0), 3001.416483, 1e-5);
    // B: dT = +10 K, dp = 0  => H = Hp + (dT/beta) ln((T0 + beta Hp)/T0) = 3000 + (10/-0.0065) ln(268.65/288.15)
    //    = 3107.80271 m;  h = 3109.32285 m.
    EXPECT_NEAR(nav::earth::H_from_Hp(3000.0, 10.0, 0.0), 3107.802709, 1e-5);
    EXPECT_NEAR(denied::altitude_from_pressure(3000.0, 10.0, 0.0), 3109.322847, 1e-5);
    // C: dT = 0, dp = +1000 Pa  => Hp_MSL = Hp(102325 Pa) = -82.91149 m, H = 3082.91149 m, h = 3084.40737 m.
    EXPECT_NEAR(nav::earth::H_from_Hp(3000.0, 0.0, 1000.0), 3082.911491, 1e-5);
    EXPECT_NEAR(denied::altitude_from_pressure(3000.0, 0.0, 1000.0), 3084.407371, 1e-5);
    // D: dT = -12 K, dp = -800 Pa, Hp = 2500 m: Simpson integration of dH/dHp = T/T_isa = 1 + dT/(T0 + beta Hp)
    //    from Hp_MSL to Hp (2e5 intervals, independent of the closed form): H = 2328.81332 m, h = 2329.66680 m.
    EXPECT_NEAR(nav::earth::H_from_Hp(2500.0, -12.0, -800.0), 2328.813325, 1e-5);
    EXPECT_NEAR(denied::altitude_from_pressure(2500.0, -12.0, -800.0), 2329.666803, 1e-5);
}

TEST(NavEarth, InsaInversesAreConsistent) {
    for (double dt : {-15.0, 0.0, 12.0}) {
        for (double dp : {-1500.0, 0.0, 900.0}) {
            for (double hp : {200.0, 3000.0, 6000.0}) {
                const double hg = nav::earth::H_from_Hp(hp, dt, dp);
                EXPECT_NEAR(nav::earth::dp_from_H(hg, hp, dt), dp, 1e-6);
                EXPECT_NEAR(synth::Hp_from_H(hg, dt, dp), hp, 1e-6);
            }
        }
    }
    EXPECT_NEAR(nav::earth::h_from_H(nav::earth::H_from_h(4321.0)), 4321.0, 1e-9);
    // dT from T and Hp: at Hp = 3000 m ISA temperature is 268.65 K.
    EXPECT_NEAR(nav::earth::dT_from(275.0, 3000.0), 6.35, 1e-12);
}

TEST(NavEarth, GravityAndRadiiMatchGeographicLib) {
    const GeographicLib::NormalGravity& ng = GeographicLib::NormalGravity::WGS84();
    const GeographicLib::Ellipsoid& el = GeographicLib::Ellipsoid::WGS84();
    for (double lat_deg : {0.0, 20.0, 45.0, 60.0, 85.0}) {
        const double lat = math::deg2rad(lat_deg);
        EXPECT_NEAR(nav::earth::normal_gravity(lat, 0.0).g_mps2, ng.SurfaceGravity(lat_deg), 1e-9);
        for (double h : {1000.0, 3000.0, 5000.0}) {
            double gy = 0, gz = 0;
            ng.Gravity(lat_deg, h, gy, gz);
            // 2nd-order altitude series vs exact normal gravity: agreement to 1e-6 m/s^2 below 5 km.
            EXPECT_NEAR(nav::earth::normal_gravity(lat, h).g_mps2, std::hypot(gy, gz), 1e-6) << lat_deg << " " << h;
        }
        const nav::earth::Radii r = nav::earth::radii(lat);
        EXPECT_NEAR(r.n_m, el.TransverseCurvatureRadius(lat_deg), 1e-6);
        EXPECT_NEAR(r.m_m, el.MeridionalCurvatureRadius(lat_deg), 1e-6);
    }
    // Equator and pole values are the defining WGS84 constants.
    EXPECT_NEAR(nav::earth::normal_gravity(0.0, 0.0).g_mps2, 9.7803253359, 1e-12);
    EXPECT_NEAR(nav::earth::normal_gravity(0.5 * math::kPi, 0.0).g_mps2, 9.8321849378, 1e-9);
}

TEST(NavEarth, EarthAndTransportRatesByHand) {
    const double lat = math::deg2rad(45.0);
    const Eigen::Vector3d wie = nav::earth::w_ie_n(lat);
    EXPECT_NEAR(wie.x(), 7.292115e-5 * std::sqrt(0.5), 1e-18);
    EXPECT_NEAR(wie.z(), -7.292115e-5 * std::sqrt(0.5), 1e-18);
    // Eastward 30 m/s: Coriolis (paper eq. force6) = (2 w vE sin lat, 0, 2 w vE cos lat) ... with vN = vD = 0:
    const Eigen::Vector3d acor = nav::earth::a_cor_n(lat, {0.0, 30.0, 0.0});
    EXPECT_NEAR(acor.x(), 2.0 * 7.292115e-5 * 30.0 * std::sin(lat), 1e-15);
    EXPECT_NEAR(acor.y(), 0.0, 1e-15);
    EXPECT_NEAR(acor.z(), 2.0 * 7.292115e-5 * 30.0 * std::cos(lat), 1e-15);
}

TEST(NavEarth, MagneticModelCornersAndBilinearCentre) {
    const Eigen::Vector3d c = nav::earth::magnetic_model_n(math::deg2rad(270.0), math::deg2rad(45.0));
    EXPECT_NEAR(c.x(), 17455.7, 1e-9);
    EXPECT_NEAR(c.z(), 52192.7, 1e-9);
    // Longitude given as -90 deg is the same meridian.
    EXPECT_NEAR((nav::earth::magnetic_model_n(math::deg2rad(-90.0), math::deg2rad(45.0)) - c).norm(), 0.0, 1e-8);
    const Eigen::Vector3d m = nav::earth::magnetic_model_n(math::deg2rad(270.5), math::deg2rad(44.5));
    EXPECT_NEAR(m.x(), 0.25 * (17455.7 + 17449.5 + 17983.9 + 17977.2), 1e-8);
}

TEST(NavEarth, DeniedVelocityIsWindPlusRotatedAirspeed) {
    denied::DeniedState prev;
    prev.lat_rad = math::deg2rad(45.0);
    prev.lon_rad = math::deg2rad(-90.0);
    prev.h_m = 3000.0;
    prev.wind_n_mps = {2.0, -3.0, 0.5};
    denied::DeniedInputs in;
    // Case 1: heading east (yaw 90 deg), level, alpha = beta = 0: v_tas_n = (0, 30, 0) => v = (2, 27, 0.5).
    in.q_nb = math::quat_from_euler({math::deg2rad(90.0), 0.0, 0.0});
    in.air.tas_mps = 30.0;
    in.air.Hp_m = 3000.0;
    denied::DeniedState s = denied::step(prev, in, 0.01, denied::HorizontalRule::kFrozenWind, denied::VerticalRule::kPressure);
    EXPECT_NEAR(s.v_n_mps.x(), 2.0, 1e-12);
    EXPECT_NEAR(s.v_n_mps.y(), 27.0, 1e-12);
    EXPECT_NEAR(s.v_n_mps.z(), 0.5, 1e-12);
    EXPECT_EQ(s.wind_n_mps, prev.wind_n_mps);
    // Altitude from pressure with dp frozen (0) and dT = 0: case A above.
    EXPECT_NEAR(s.h_m, 3001.416483, 1e-5);
    // Latitude unchanged to first order of vN = 2 m/s: dlat = 0.01 * 2/(M + h).
    EXPECT_NEAR(s.lat_rad - prev.lat_rad, 0.02 / (nav::earth::radii(prev.lat_rad).m_m + s.h_m), 1e-15);
    // Case 2: yaw 0, pitch 0, bank 90 deg, alpha = 0.1 rad: v_tas_b = 30 (cos 0.1, 0, sin 0.1);
    //   R_x(90 deg) maps body z to NED -y: v_tas_n = (30 cos 0.1, -30 sin 0.1, 0).
    in.q_nb = math::quat_from_euler({0.0, 0.0, math::deg2rad(90.0)});
    in.air.aoa_rad = 0.1;
    prev.wind_n_mps = {1.0, 1.0, 1.0};
    s = denied::step(prev, in, 0.01, denied::HorizontalRule::kFrozenWind, denied::VerticalRule::kPressure);
    EXPECT_NEAR(s.v_n_mps.x(), 1.0 + 30.0 * std::cos(0.1), 1e-12);
    EXPECT_NEAR(s.v_n_mps.y(), 1.0 - 30.0 * std::sin(0.1), 1e-12);
    EXPECT_NEAR(s.v_n_mps.z(), 1.0, 1e-12);
    // Airspeed integration forces the vertical wind to zero: v_D = [R v_tas_b]_D = 0, h = h(k-1).
    s = denied::step(prev, in, 0.01, denied::HorizontalRule::kFrozenWind, denied::VerticalRule::kAirspeedIntegration);
    EXPECT_NEAR(s.v_n_mps.z(), 0.0, 1e-12);
    EXPECT_EQ(s.wind_n_mps.z(), 0.0);
    EXPECT_NEAR(s.h_m, prev.h_m, 1e-12);
    // Vertical integration keeps the frozen vertical wind: h = h(k-1) - dt * 1.0.
    s = denied::step(prev, in, 0.01, denied::HorizontalRule::kFrozenWind, denied::VerticalRule::kIntegration);
    EXPECT_NEAR(s.h_m, prev.h_m - 0.01, 1e-12);
}

TEST(NavEarth, DoubleIntegrationByHand) {
    // At rest on the equator at h = 0 with q = identity and f_b = (1, 0, -g): v_dot = R f + g_n = (1, 0, 0),
    // so after one step v = (0.01, 0, 0) (transport rate and Coriolis vanish at v = 0).
    denied::DeniedState prev;
    denied::DeniedInputs in;
    in.air.tas_mps = 20.0;
    in.f_b_mps2 = {1.0, 0.0, -nav::earth::normal_gravity(0.0, 0.0).g_mps2};
    const denied::DeniedState s =
        denied::step(prev, in, 0.01, denied::HorizontalRule::kDoubleIntegration, denied::VerticalRule::kIntegration);
    EXPECT_NEAR(s.v_n_mps.x(), 0.01, 1e-15);
    EXPECT_NEAR(s.v_n_mps.y(), 0.0, 1e-15);
    EXPECT_NEAR(s.v_n_mps.z(), 0.0, 1e-15);
    // Wind output = v - R v_tas = (0.01 - 20, 0, 0).
    EXPECT_NEAR(s.wind_n_mps.x(), 0.01 - 20.0, 1e-12);
}
