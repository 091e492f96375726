// The viewer channels' derived quantities against values worked out by hand (viewer_math.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "io/viewer/viewer_math.hpp"

using namespace gdnav;
using math::deg2rad;

namespace {

math::Vec3 rotate(const math::Quat& q, const math::Vec3& v) { return q * v; }

// WGS84 radii of curvature at 45 deg (tests/unit/metrics/nav_errors_test.cpp: by hand from a and e^2).
constexpr double kN45 = 6388838.290;
constexpr double kM45 = 6367381.816;

}  // namespace

// Level flight heading north: the body's forward axis is north = ENU +y, i.e. the FLU body is the ENU frame turned
// +90 deg about up: q = (cos 45, 0, 0, sin 45).
TEST(ViewerMath, HeadingNorthIsNinetyDegreesAboutUpInEnu) {
    const math::Quat q = io::viewer::quat_enu_flu(math::quat_from_euler({0.0, 0.0, 0.0}));
    const double h = std::sqrt(0.5);
    EXPECT_NEAR(q.w(), h, 1e-15);
    EXPECT_NEAR(q.x(), 0.0, 1e-15);
    EXPECT_NEAR(q.y(), 0.0, 1e-15);
    EXPECT_NEAR(q.z(), h, 1e-15);
}

// Level flight heading east: forward = east = ENU +x, left = north = +y, up = +z: the identity.
TEST(ViewerMath, HeadingEastIsTheIdentityInEnu) {
    const math::Quat q = io::viewer::quat_enu_flu(math::quat_from_euler({deg2rad(90.0), 0.0, 0.0}));
    EXPECT_NEAR(q.w(), 1.0, 1e-15);
    EXPECT_NEAR(q.x(), 0.0, 1e-15);
    EXPECT_NEAR(q.y(), 0.0, 1e-15);
    EXPECT_NEAR(q.z(), 0.0, 1e-15);
}

// Yaw psi = 30 deg, pitch theta = 10 deg: the forward axis in NED is (cos th cos psi, cos th sin psi, -sin th), so in
// ENU (cos th sin psi, cos th cos psi, sin th) — nose up is +z.
TEST(ViewerMath, ForwardAxisPointsAlongTheNoseInEnu) {
    const double psi = deg2rad(30.0), th = deg2rad(10.0);
    const math::Quat q = io::viewer::quat_enu_flu(math::quat_from_euler({psi, th, 0.0}));
    const math::Vec3 fwd = rotate(q, {1.0, 0.0, 0.0});
    EXPECT_NEAR(fwd.x(), std::cos(th) * std::sin(psi), 1e-14);
    EXPECT_NEAR(fwd.y(), std::cos(th) * std::cos(psi), 1e-14);
    EXPECT_NEAR(fwd.z(), std::sin(th), 1e-14);
    EXPECT_GE(q.w(), 0.0);
}

// Heading north, bank phi = 20 deg (right wing down): the right wing (east) dips, so the roof (FLU +z) tilts east:
// up axis in ENU = (sin phi, 0, cos phi); the left wing (FLU +y) points west and up: (-cos phi, 0, sin phi).
TEST(ViewerMath, BankTiltsTheRoofTowardsTheLoweredWing) {
    const double phi = deg2rad(20.0);
    const math::Quat q = io::viewer::quat_enu_flu(math::quat_from_euler({0.0, 0.0, phi}));
    const math::Vec3 up = rotate(q, {0.0, 0.0, 1.0});
    const math::Vec3 left = rotate(q, {0.0, 1.0, 0.0});
    EXPECT_NEAR(up.x(), std::sin(phi), 1e-14);
    EXPECT_NEAR(up.y(), 0.0, 1e-14);
    EXPECT_NEAR(up.z(), std::cos(phi), 1e-14);
    EXPECT_NEAR(left.x(), -std::cos(phi), 1e-14);
    EXPECT_NEAR(left.y(), 0.0, 1e-14);
    EXPECT_NEAR(left.z(), std::sin(phi), 1e-14);
}

// 100 m straight up is (0, 0, 100); a small step north or east is the radius of curvature times the angle
// (M dlat, N cos(lat) dlon at 45 deg and h = 0; second-order terms < 1 mm at these distances).
TEST(ViewerMath, EnuOffsetsOfSmallDisplacements) {
    const earth::Geodetic o{deg2rad(10.0), deg2rad(45.0), 0.0};
    const math::Vec3 up = io::viewer::enu_offset_m(o, {o.lon_rad, o.lat_rad, 100.0});
    EXPECT_NEAR(up.x(), 0.0, 1e-6);
    EXPECT_NEAR(up.y(), 0.0, 1e-6);
    EXPECT_NEAR(up.z(), 100.0, 1e-6);
    const double d = 1e-5;  // rad: 64 m
    const math::Vec3 north = io::viewer::enu_offset_m(o, {o.lon_rad, o.lat_rad + d, 0.0});
    EXPECT_NEAR(north.x(), 0.0, 1e-6);
    EXPECT_NEAR(north.y(), kM45 * d, 1e-3);
    EXPECT_NEAR(north.z(), 0.0, 1e-3);
    const math::Vec3 east = io::viewer::enu_offset_m(o, {o.lon_rad + d, o.lat_rad, 0.0});
    EXPECT_NEAR(east.x(), kN45 * std::cos(o.lat_rad) * d, 1e-3);
    EXPECT_NEAR(east.y(), 0.0, 1e-3);
    EXPECT_NEAR(east.z(), 0.0, 1e-3);
}

TEST(ViewerMath, TimePartsSplitNanoseconds) {
    // GNSS loss of the paper scenarios + 10 ns
    const io::viewer::TimeParts t = io::viewer::time_parts(150'000'000'010ULL);
    EXPECT_EQ(t.sec, 150u);
    EXPECT_EQ(t.nsec, 10u);
    const io::viewer::TimeParts h = io::viewer::time_parts(3'600'999'999'999ULL);
    EXPECT_EQ(h.sec, 3600u);
    EXPECT_EQ(h.nsec, 999'999'999u);
}

// Estimate: yaw +1 deg, 5 m high, 1e-5 rad north at 45 deg, v_E 1 m/s more, TAS 0.5 m/s more.
TEST(ViewerMath, NavErrorValuesInViewerUnits) {
    metrics::NavState truth;
    truth.lat_rad = deg2rad(45.0);
    truth.lon_rad = deg2rad(10.0);
    truth.h_m = 0.0;
    truth.v_n_mps = {30.0, 40.0, 0.0};  // ground speed 50 m/s
    truth.tas_mps = 52.0;
    metrics::NavState est = truth;
    est.q_nb = math::quat_from_euler({deg2rad(1.0), 0.0, 0.0});
    est.h_m = 5.0;
    est.lat_rad += 1e-5;
    est.v_n_mps = {30.0, 41.0, 0.0};
    est.tas_mps = 52.5;
    const io::viewer::NavErrorValues v = io::viewer::nav_error_values(est, truth, {kN45, kM45});
    EXPECT_NEAR(v.att_err_deg, 1.0, 1e-12);
    EXPECT_NEAR(v.yaw_err_deg, 1.0, 1e-12);
    EXPECT_NEAR(v.pitch_err_deg, 0.0, 1e-12);
    EXPECT_NEAR(v.bank_err_deg, 0.0, 1e-12);
    EXPECT_NEAR(v.hor_err_m, kM45 * 1e-5, 1e-6);  // (lat_est - lat) (M0 + h), h = 0
    EXPECT_DOUBLE_EQ(v.alt_err_m, 5.0);
    EXPECT_DOUBLE_EQ(v.vn_err_mps, 0.0);
    EXPECT_DOUBLE_EQ(v.ve_err_mps, 1.0);
    EXPECT_NEAR(v.gs_err_mps, 0.8035432, 1e-7);  // sqrt(30^2 + 41^2) - 50 = sqrt(2581) - 50
    EXPECT_DOUBLE_EQ(v.tas_err_mps, 0.5);
}
