// Navigation errors against hand computations (conventions of docs/montecarlo.md, "nav_recorder: errors, online
// metrics and files").
#include <gtest/gtest.h>

#include <cmath>

#include "metrics/nav_errors.hpp"

using namespace gdnav;
using metrics::NavState;
using math::deg2rad;

namespace {

NavState at(double lat_deg, double lon_deg, double h_m, const math::Vec3& v) {
    NavState s;
    s.lat_rad = deg2rad(lat_deg);
    s.lon_rad = deg2rad(lon_deg);
    s.h_m = h_m;
    s.v_n_mps = v;
    return s;
}

// WGS84 radii of curvature at 45 deg, computed by hand from a = 6378137 m, e^2 = 0.00669437999014:
// N = a / sqrt(1 - e^2/2) = 6388838.290 m, M = a (1 - e^2) / (1 - e^2/2)^1.5 = 6367381.816 m.
constexpr double kN45 = 6388838.290;
constexpr double kM45 = 6367381.816;

}  // namespace

TEST(NavErrors, RadiiAt45DegreesMatchHandValues) {
    const earth::Radii r = earth::radii(deg2rad(45.0));
    EXPECT_NEAR(r.n_m, kN45, 1e-3);
    EXPECT_NEAR(r.m_m, kM45, 1e-3);
}

TEST(NavErrors, HorizontalCrossAlongForEastboundTrack) {
    const earth::Radii r0{kN45, kM45};
    const NavState truth = at(45.0, -90.0, 1000.0, {0.0, 30.0, 0.0});  // flying east: chi = 90 deg
    // Estimate 100 m north and 50 m east of the truth.
    const double lat_est = truth.lat_rad + 100.0 / (kM45 + 1000.0);
    const double lon_est = truth.lon_rad + 50.0 / ((kN45 + 1000.0) * std::cos(truth.lat_rad));
    const auto e = metrics::horizontal_error(lat_est, lon_est, truth, r0);
    EXPECT_NEAR(e.north_m, 100.0, 1e-6);
    EXPECT_NEAR(e.east_m, 50.0, 1e-6);
    EXPECT_NEAR(e.hor_m, std::sqrt(100.0 * 100.0 + 50.0 * 50.0), 1e-6);
    EXPECT_NEAR(e.cross_m, -100.0, 1e-6);  // north of an eastbound track: to the left
    EXPECT_NEAR(e.along_m, 50.0, 1e-6);    // east: ahead
}

TEST(NavErrors, HorizontalCrossAlongForNorthboundAndSouthwestTracks) {
    const earth::Radii r0{kN45, kM45};
    NavState truth = at(45.0, -90.0, 0.0, {30.0, 0.0, 0.0});  // chi = 0
    const double lat_est = truth.lat_rad + 100.0 / kM45;
    const double lon_est = truth.lon_rad + 50.0 / (kN45 * std::cos(truth.lat_rad));
    auto e = metrics::horizontal_error(lat_est, lon_est, truth, r0);
    EXPECT_NEAR(e.cross_m, 50.0, 1e-6);   // east of a northbound track: to the right
    EXPECT_NEAR(e.along_m, 100.0, 1e-6);  // north: ahead
    // Southwest (chi = -135 deg): ahead is (-1, -1)/sqrt2, right is (1, -1)/sqrt2 (N, E).
    truth.v_n_mps = {-20.0, -20.0, 0.0};
    e = metrics::horizontal_error(lat_est, lon_est, truth, r0);
    EXPECT_NEAR(e.along_m, (-100.0 - 50.0) / std::sqrt(2.0), 1e-6);
    EXPECT_NEAR(e.cross_m, (100.0 - 50.0) / std::sqrt(2.0), 1e-6);
    // The decomposition keeps the norm.
    EXPECT_NEAR(std::hypot(e.cross_m, e.along_m), e.hor_m, 1e-9);
}

TEST(NavErrors, EulerErrorsWrapYawAcrossPlusMinus180) {
    NavState truth = at(45.0, -90.0, 0.0, {30.0, 0.0, 0.0});
    NavState est = truth;
    truth.q_nb = math::quat_from_euler({deg2rad(179.0), deg2rad(10.0), deg2rad(5.0)});
    est.q_nb = math::quat_from_euler({deg2rad(-179.0), deg2rad(10.5), deg2rad(5.0)});
    const auto e = metrics::nav_errors(est, truth, earth::radii(truth.lat_rad));
    EXPECT_NEAR(e.yaw_rad, deg2rad(2.0), 1e-12);  // -179 - 179 = -358 -> +2 deg
    EXPECT_NEAR(e.pitch_rad, deg2rad(0.5), 1e-12);
    EXPECT_NEAR(e.bank_rad, 0.0, 1e-12);
}

TEST(NavErrors, RotationAngleIsTheNormOfTheRotationVector) {
    NavState truth = at(45.0, -90.0, 0.0, {30.0, 0.0, 0.0});
    truth.q_nb = math::quat_from_euler({deg2rad(30.0), deg2rad(-4.0), deg2rad(20.0)});
    NavState est = truth;
    // A body-frame rotation of 0.02 rad about (2, -1, 2)/3 and a NED-frame one of 0.03 rad about z.
    est.q_nb = truth.q_nb * math::quat_from_rotv(math::Vec3(2.0, -1.0, 2.0) / 3.0 * 0.02);
    EXPECT_NEAR(metrics::nav_errors(est, truth, earth::radii(truth.lat_rad)).rot_rad, 0.02, 1e-12);
    est.q_nb = math::quat_from_rotv(math::Vec3(0.0, 0.0, 0.03)) * truth.q_nb;
    EXPECT_NEAR(metrics::nav_errors(est, truth, earth::radii(truth.lat_rad)).rot_rad, 0.03, 1e-12);
}

TEST(NavErrors, AirDataAltitudeAndVelocityAreEstimateMinusTruth) {
    NavState truth = at(45.0, -90.0, 2500.0, {20.0, -10.0, 1.0});
    truth.tas_mps = 29.0;
    truth.aoa_rad = 0.05;
    truth.aos_rad = -0.01;
    truth.dT_K = 3.0;
    NavState est = truth;
    est.tas_mps = 29.5;
    est.aoa_rad = 0.04;
    est.aos_rad = 0.0;
    est.dT_K = 2.5;
    est.h_m = 2490.0;
    est.v_n_mps = {21.0, -12.0, 1.5};
    const auto e = metrics::nav_errors(est, truth, earth::radii(truth.lat_rad));
    EXPECT_NEAR(e.tas_mps, 0.5, 1e-12);
    EXPECT_NEAR(e.aoa_rad, -0.01, 1e-12);
    EXPECT_NEAR(e.aos_rad, 0.01, 1e-12);
    EXPECT_NEAR(e.dT_K, -0.5, 1e-12);
    EXPECT_NEAR(e.h_m, -10.0, 1e-12);
    EXPECT_NEAR(e.v_n_mps.x(), 1.0, 1e-12);
    EXPECT_NEAR(e.v_n_mps.y(), -2.0, 1e-12);
    EXPECT_EQ(e.hor_m, 0.0);
    EXPECT_EQ(e.rot_rad, 0.0);
}
