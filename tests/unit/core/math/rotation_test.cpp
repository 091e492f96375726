#include <gtest/gtest.h>

#include "math/rotation.hpp"

using namespace gdnav::math;

TEST(Rotation, EulerRoundTrip) {
    const Euler e{deg2rad(-72.0), deg2rad(3.5), deg2rad(-10.0)};
    const Euler r = euler_from_quat(quat_from_euler(e));
    EXPECT_NEAR(r.yaw_rad, e.yaw_rad, 1e-14);
    EXPECT_NEAR(r.pitch_rad, e.pitch_rad, 1e-14);
    EXPECT_NEAR(r.bank_rad, e.bank_rad, 1e-14);
}

TEST(Rotation, YawNinetyMapsBodyXToEast) {
    const Vec3 v = quat_from_euler({deg2rad(90.0), 0.0, 0.0}) * Vec3::UnitX();
    EXPECT_NEAR(v.x(), 0.0, 1e-15);
    EXPECT_NEAR(v.y(), 1.0, 1e-15);
}

TEST(Rotation, RotvRoundTripAndAngle) {
    const Vec3 rv(0.3, -0.2, 0.1);
    EXPECT_NEAR((rotv_from_quat(quat_from_rotv(rv)) - rv).norm(), 0.0, 1e-14);
    EXPECT_NEAR(angle_between(Quat::Identity(), quat_from_rotv(rv)), rv.norm(), 1e-14);
}

TEST(Rotation, QuatDerivativeMatchesFiniteDifference) {
    const Quat q = quat_from_euler({0.4, -0.1, 0.2});
    const Vec3 w(0.1, -0.3, 0.2);
    const double dt = 1e-7;
    const Quat q2 = q * quat_from_rotv(w * dt);
    const Eigen::Vector4d fd = (to_wxyz(q2) - to_wxyz(q)) / dt;
    EXPECT_NEAR((fd - quat_derivative(q, w)).norm(), 0.0, 1e-6);
}

TEST(Rotation, WindToBodyMatchesAirspeedVector) {
    const double a = deg2rad(4.0), b = deg2rad(-2.0);
    const Vec3 v = dcm_body_from_wind(a, b) * Vec3(25.0, 0.0, 0.0);
    EXPECT_NEAR((v - vtas_body(25.0, a, b)).norm(), 0.0, 1e-13);
    const AirAngles aa = air_angles(v);
    EXPECT_NEAR(aa.aoa_rad, a, 1e-14);
    EXPECT_NEAR(aa.aos_rad, b, 1e-14);
}

TEST(Rotation, Wrap) {
    EXPECT_NEAR(wrap_pi(3.0 * kPi / 2.0), -kPi / 2.0, 1e-15);
    EXPECT_DOUBLE_EQ(wrap_pi(kPi), kPi);
    EXPECT_NEAR(wrap_2pi(-kPi / 2.0), 3.0 * kPi / 2.0, 1e-15);
}
