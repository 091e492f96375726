// Earth model: geodesy, radii, rates, normal and true gravity, magnetic field.
#include <gtest/gtest.h>

#include <GeographicLib/Ellipsoid.hpp>
#include <GeographicLib/NormalGravity.hpp>
#include <cmath>

#include "earth/gravity.hpp"
#include "earth/magnetic.hpp"
#include "earth/wgs84.hpp"

using namespace gdnav;
using earth::Vec3;
using math::deg2rad;

TEST(Earth, NormalGravityAt45DegMatchesIndependentValue) {
    // WGS84 normal gravity on the ellipsoid at 45 deg latitude. Hand evaluation of Somigliana's closed form with the
    // WGS84 constants gives 9.8061977693 m/s^2; GeographicLib (which derives gravity from GM, J2 and w instead of
    // gamma_e, gamma_p) gives the same to 1e-10. (The often quoted 9.806199 is the truncated 1980 series formula.)
    EXPECT_NEAR(earth::normal_gravity_mps2(deg2rad(45.0), 0.0), 9.8061977693, 1e-9);
    EXPECT_NEAR(earth::normal_gravity_mps2(deg2rad(45.0), 0.0),
                GeographicLib::NormalGravity::WGS84().SurfaceGravity(45.0), 1e-9);
    EXPECT_NEAR(earth::normal_gravity_mps2(0.0, 0.0), 9.7803253359, 1e-12);
    EXPECT_NEAR(earth::normal_gravity_mps2(deg2rad(90.0), 0.0), 9.8321849378, 1e-9);
}

TEST(Earth, NormalGravityWithAltitudeMatchesGeographicLib) {
    // GeographicLib evaluates the closed-form normal potential of the WGS84 ellipsoid (independent of our series).
    const GeographicLib::NormalGravity& ng = GeographicLib::NormalGravity::WGS84();
    for (double lat : {0.0, 30.0, 45.0, 60.0, 89.0}) {
        for (double h : {0.0, 1000.0, 2700.0, 5000.0}) {
            double gy = 0.0, gz = 0.0;
            ng.Gravity(lat, h, gy, gz);
            const double ref = std::hypot(gy, gz);
            EXPECT_NEAR(earth::normal_gravity_mps2(deg2rad(lat), h), ref, 1e-6) << "lat " << lat << " h " << h;
        }
    }
}

TEST(Earth, RadiiMatchGeographicLib) {
    const GeographicLib::Ellipsoid& el = GeographicLib::Ellipsoid::WGS84();
    for (double lat : {0.0, 20.0, 45.0, 70.0, 89.9}) {
        const earth::Radii r = earth::radii(deg2rad(lat));
        EXPECT_NEAR(r.n_m, el.TransverseCurvatureRadius(lat), 1e-6);
        EXPECT_NEAR(r.m_m, el.MeridionalCurvatureRadius(lat), 1e-6);
    }
}

TEST(Earth, GeodeticEcefRoundTripAndKnownPoints) {
    const Vec3 eq = earth::ecef_from_geodetic({0.0, 0.0, 0.0});
    EXPECT_NEAR(eq.x(), 6378137.0, 1e-6);
    EXPECT_NEAR(eq.norm(), 6378137.0, 1e-6);
    const Vec3 pole = earth::ecef_from_geodetic({0.3, deg2rad(90.0), 100.0});
    EXPECT_NEAR(pole.z(), 6356752.314245 + 100.0, 1e-5);  // b = a (1 - f)
    for (double lat : {-80.0, -45.0, 0.0, 45.0, 89.5}) {
        for (double lon : {-179.0, -90.0, 0.0, 135.0}) {
            for (double h : {-100.0, 0.0, 2700.0, 10000.0}) {
                const earth::Geodetic p{deg2rad(lon), deg2rad(lat), h};
                const earth::Geodetic q = earth::geodetic_from_ecef(earth::ecef_from_geodetic(p));
                EXPECT_NEAR(q.lat_rad, p.lat_rad, 1e-12);
                EXPECT_NEAR(math::wrap_pi(q.lon_rad - p.lon_rad), 0.0, 1e-12);
                EXPECT_NEAR(q.h_m, p.h_m, 1e-6);
            }
        }
    }
}

TEST(Earth, PositionRateMatchesEcefDisplacement) {
    // Moving at v_n for dt displaces the ECEF position by R_en v_n dt (to second order in dt).
    const earth::Geodetic p{deg2rad(-90.0), deg2rad(45.0), 2700.0};
    const Vec3 v_n(20.0, -15.0, 3.0);
    const double dt = 1e-2;
    const Vec3 rate = earth::position_rate(p.lat_rad, p.h_m, v_n);
    const earth::Geodetic q{p.lon_rad + rate.x() * dt, p.lat_rad + rate.y() * dt, p.h_m + rate.z() * dt};
    const Vec3 d = earth::ecef_from_geodetic(q) - earth::ecef_from_geodetic(p);
    const Vec3 expected = earth::dcm_ecef_from_ned(p.lon_rad, p.lat_rad) * v_n * dt;
    EXPECT_LT((d - expected).norm(), 1e-6);
}

TEST(Earth, EarthAndTransportRatesMatchFrameKinematics) {
    const double lat = deg2rad(45.0), lon = deg2rad(-90.0), h = 2700.0;
    // Earth rate: w_ie^n expressed in ECEF is (0, 0, w_ie).
    const Vec3 w_e = earth::dcm_ecef_from_ned(lon, lat) * earth::earth_rate_n(lat);
    EXPECT_NEAR(w_e.x(), 0.0, 1e-18);
    EXPECT_NEAR(w_e.y(), 0.0, 1e-18);
    EXPECT_NEAR(w_e.z(), earth::wgs84::kOmegaIE_rps, 1e-18);
    // Transport rate: R_en(t + dt) = R_en(t) (I + skew(w_en^n) dt) + O(dt^2).
    const Vec3 v_n(25.0, 12.0, 0.0);
    const double dt = 1e-3;
    const Vec3 rate = earth::position_rate(lat, h, v_n);
    const math::Mat3 r0 = earth::dcm_ecef_from_ned(lon, lat);
    const math::Mat3 r1 = earth::dcm_ecef_from_ned(lon + rate.x() * dt, lat + rate.y() * dt);
    const math::Mat3 s = (r0.transpose() * r1 - math::Mat3::Identity()) / dt;
    const Vec3 w_num(0.5 * (s(2, 1) - s(1, 2)), 0.5 * (s(0, 2) - s(2, 0)), 0.5 * (s(1, 0) - s(0, 1)));
    const Vec3 w_en = earth::transport_rate_n(lat, h, v_n);
    EXPECT_LT((w_num - w_en).norm(), 1e-3 * w_en.norm());
    // Coriolis is 2 w_ie x v.
    EXPECT_LT((earth::coriolis_n(lat, v_n) - 2.0 * earth::earth_rate_n(lat).cross(v_n)).norm(), 1e-15);
}

TEST(Earth, GeopotentialConversion) {
    // Spherical formula with R_E = 6356766 m: H(5000 m) = 6356766 * 5000 / 6361766 = 4996.070 m.
    EXPECT_NEAR(earth::geopotential_from_geometric(5000.0), 4996.0702, 1e-4);
    for (double h : {-200.0, 0.0, 2534.5, 12000.0})
        EXPECT_NEAR(earth::geometric_from_geopotential(earth::geopotential_from_geometric(h)), h, 1e-9);
}

TEST(Earth, TrueGravityHasOffsetModulusAndTiltAboutHorizontalAxis) {
    earth::EarthTruthParams p;
    p.dg_mps2 = 2e-4;
    p.tilt_rad = deg2rad(0.01);
    p.tilt_axis_bearing_rad = deg2rad(30.0);
    const earth::TrueGravity tg(p);
    const double g = earth::normal_gravity_mps2(deg2rad(45.0), 2700.0);
    const Vec3 gt = tg.at(deg2rad(45.0), 2700.0);
    EXPECT_NEAR(gt.norm(), g + 2e-4, 1e-12);
    // Rotating (0, 0, G) about (cos b, sin b, 0) by d gives G (sin b sin d, -cos b sin d, cos d).
    const double G = g + 2e-4, b = deg2rad(30.0), d = deg2rad(0.01);
    EXPECT_NEAR(gt.x(), G * std::sin(b) * std::sin(d), 1e-12);
    EXPECT_NEAR(gt.y(), -G * std::cos(b) * std::sin(d), 1e-12);
    EXPECT_NEAR(gt.z(), G * std::cos(d), 1e-12);
}

TEST(Earth, TruthDrawsHaveTheSpecifiedSpread) {
    rnd::Stream s = rnd::Stream::derive(7, 0, "earth_truth");
    const int n = 20000;
    double sdg = 0.0, stilt = 0.0;
    Vec3 smag = Vec3::Zero();
    for (int i = 0; i < n; ++i) {
        const earth::EarthTruthParams p = earth::draw_earth_truth(s);
        sdg += p.dg_mps2 * p.dg_mps2;
        stilt += p.tilt_rad * p.tilt_rad;
        smag += p.mag_dev_n_nT.cwiseProduct(p.mag_dev_n_nT);
        const double bdeg = math::rad2deg(p.tilt_axis_bearing_rad);
        ASSERT_GE(bdeg, -179.0 - 1e-9);
        ASSERT_LE(bdeg, 180.0 + 1e-9);
        ASSERT_NEAR(bdeg, std::round(bdeg), 1e-9);
    }
    // 20000 samples: the sample std has a relative standard error of 0.5 %; allow 3 %.
    EXPECT_NEAR(std::sqrt(sdg / n), 1e-4, 3e-6);
    EXPECT_NEAR(std::sqrt(stilt / n), deg2rad(0.0028), 0.03 * deg2rad(0.0028));
    EXPECT_NEAR(std::sqrt(smag.x() / n), 138.0, 0.03 * 138.0);
    EXPECT_NEAR(std::sqrt(smag.y() / n), 89.0, 0.03 * 89.0);
    EXPECT_NEAR(std::sqrt(smag.z() / n), 165.0, 0.03 * 165.0);
}

TEST(Earth, WisconsinMagneticModelInterpolatesTheCorners) {
    const auto m = earth::MagneticModel::load(std::string(GDNAV_SOURCE_DIR) + "/config/earth/magnetic_wisconsin.yaml");
    // Corner values of the reference table (nT).
    const Vec3 ul = m.field_n_nT(deg2rad(45.0), deg2rad(-90.0));
    EXPECT_NEAR(ul.x(), 17455.7, 1e-6);
    EXPECT_NEAR(ul.y(), -764.6, 1e-6);
    EXPECT_NEAR(ul.z(), 52192.7, 1e-6);
    const Vec3 lr = m.field_n_nT(deg2rad(44.0), deg2rad(271.0));  // 271 E == 89 W
    EXPECT_NEAR(lr.x(), 17977.2, 1e-6);
    EXPECT_NEAR(lr.y(), -997.0, 1e-6);
    EXPECT_NEAR(lr.z(), 51538.4, 1e-6);
    // Centre = mean of the corners (hand computation).
    const Vec3 c = m.field_n_nT(deg2rad(44.5), deg2rad(-89.5));
    EXPECT_NEAR(c.x(), (17455.7 + 17449.5 + 17983.9 + 17977.2) / 4.0, 1e-6);
    EXPECT_NEAR(c.z(), (52192.7 + 52158.5 + 51571.5 + 51538.4) / 4.0, 1e-6);
    // Linear extrapolation north of the square: B(46) = 2 B(45) - B(44) on the west edge.
    const Vec3 n = m.field_n_nT(deg2rad(46.0), deg2rad(-90.0));
    EXPECT_NEAR(n.x(), 2.0 * 17455.7 - 17983.9, 1e-6);
    // True field = model + deviation.
    const Vec3 dev(10.0, -20.0, 30.0);
    EXPECT_LT((m.true_field_n_nT(deg2rad(45.0), deg2rad(-90.0), dev) - ul - dev).norm(), 1e-9);
}

TEST(Earth, BadMagneticFileNamesTheKey) {
    const std::string text =
        "lat_min_deg: 45\nlat_max_deg: 44\nlon_min_deg: -90\nlon_max_deg: -89\n"
        "b_n_lat_min_lon_min_nT: [1, 2, 3]\nb_n_lat_min_lon_max_nT: [1, 2, 3]\n"
        "b_n_lat_max_lon_min_nT: [1, 2, 3]\nb_n_lat_max_lon_max_nT: [1, 2, 3]\n";
    try {
        (void)earth::MagneticModel::from_config(config::Config::parse(text, "mag.yaml"));
        FAIL() << "no ConfigError";
    } catch (const config::ConfigError& e) {
        EXPECT_NE(std::string(e.what()).find("lat_max_deg"), std::string::npos) << e.what();
    }
}
