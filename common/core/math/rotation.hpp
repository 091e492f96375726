#pragma once
// The one rotation toolkit of gdnav: Hamilton quaternions (scalar first, Eigen::Quaterniond), 3-2-1 Euler
// angles (yaw psi, pitch theta, bank xi), direction cosine matrices, rotation vectors and angle helpers.
// Convention: q_nb rotates body components into NED, v_n = q_nb * v_b = R(q_nb) v_b.
#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

namespace gdnav::core::math {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using Quat = Eigen::Quaterniond;

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;  // multiply degrees by kDeg to get radians

constexpr double deg2rad(double deg) { return deg * kDeg; }
constexpr double rad2deg(double rad) { return rad / kDeg; }

// Wraps an angle to (-pi, pi].
double wrap_pi(double a);
// Wraps an angle to [0, 2 pi).
double wrap_2pi(double a);

// Skew-symmetric (cross-product) matrix: skew(a) * b == a.cross(b).
Mat3 skew(const Vec3& a);

// Euler 3-2-1 (yaw, pitch, bank) <-> quaternion / DCM of the body->NED rotation.
struct Euler {
    double yaw_rad{0.0};
    double pitch_rad{0.0};
    double bank_rad{0.0};
};
Quat quat_from_euler(const Euler& e);
Euler euler_from_quat(const Quat& q_nb);
Mat3 dcm_from_euler(const Euler& e);
Euler euler_from_dcm(const Mat3& r_nb);

// Rotation vector (axis * angle) <-> quaternion (exponential and logarithmic maps).
Quat quat_from_rotv(const Vec3& rotv);
Vec3 rotv_from_quat(const Quat& q);

// Rotation angle between two attitudes, |log(q_a^-1 q_b)| in [0, pi].
double angle_between(const Quat& q_a, const Quat& q_b);

// Quaternion kinematics: dq/dt = 0.5 * q (x) [0, w]. Returns the derivative as a 4-vector (w, x, y, z).
Eigen::Vector4d quat_derivative(const Quat& q, const Vec3& w_rps);

// Quaternion <-> 4-vector (w, x, y, z), the order used on every topic.
Eigen::Vector4d to_wxyz(const Quat& q);
Quat from_wxyz(const Eigen::Vector4d& v);

// Body-to-wind (air-path) angles: v_tas_b = V (cos a cos b, sin b, sin a cos b).
Vec3 vtas_body(double tas_mps, double aoa_rad, double aos_rad);
struct AirAngles {
    double tas_mps{0.0};
    double aoa_rad{0.0};
    double aos_rad{0.0};
};
AirAngles air_angles(const Vec3& vtas_b);
// Rotation from wind (air-path) axes to body axes: Euler (yaw = -aos, pitch = aoa, bank = 0).
Mat3 dcm_body_from_wind(double aoa_rad, double aos_rad);

}  // namespace gdnav::core::math
namespace gdnav { namespace math = core::math; }  // the short name (docs/architecture.md, "Namespaces")
