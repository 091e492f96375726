#include "math/rotation.hpp"

#include <algorithm>

namespace gdnav::core::math {

double wrap_pi(double a) {
    double r = std::fmod(a + kPi, 2.0 * kPi);
    if (r <= 0.0) r += 2.0 * kPi;
    return r - kPi;
}

double wrap_2pi(double a) {
    double r = std::fmod(a, 2.0 * kPi);
    if (r < 0.0) r += 2.0 * kPi;
    return r;
}

Mat3 skew(const Vec3& a) {
    Mat3 m;
    m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
    return m;
}

Quat quat_from_euler(const Euler& e) {
    const double cy = std::cos(0.5 * e.yaw_rad), sy = std::sin(0.5 * e.yaw_rad);
    const double cp = std::cos(0.5 * e.pitch_rad), sp = std::sin(0.5 * e.pitch_rad);
    const double cb = std::cos(0.5 * e.bank_rad), sb = std::sin(0.5 * e.bank_rad);
    Quat q(cy * cp * cb + sy * sp * sb, cy * cp * sb - sy * sp * cb, cy * sp * cb + sy * cp * sb,
           sy * cp * cb - cy * sp * sb);
    if (q.w() < 0.0) q.coeffs() = -q.coeffs();
    return q;
}

Euler euler_from_dcm(const Mat3& r) {
    Euler e;
    e.yaw_rad = std::atan2(r(1, 0), r(0, 0));
    e.pitch_rad = -std::asin(std::clamp(r(2, 0), -1.0, 1.0));
    e.bank_rad = std::atan2(r(2, 1), r(2, 2));
    return e;
}

Euler euler_from_quat(const Quat& q) { return euler_from_dcm(q.toRotationMatrix()); }

Mat3 dcm_from_euler(const Euler& e) { return quat_from_euler(e).toRotationMatrix(); }

Quat quat_from_rotv(const Vec3& rotv) {
    const double angle = rotv.norm();
    if (angle < 1e-12) {
        Quat q(1.0, 0.5 * rotv.x(), 0.5 * rotv.y(), 0.5 * rotv.z());
        return q.normalized();
    }
    const Vec3 axis = rotv / angle;
    const double s = std::sin(0.5 * angle);
    return Quat(std::cos(0.5 * angle), axis.x() * s, axis.y() * s, axis.z() * s);
}

Vec3 rotv_from_quat(const Quat& q_in) {
    Quat q = q_in;
    if (q.w() < 0.0) q.coeffs() = -q.coeffs();
    const Vec3 v = q.vec();
    const double sn = v.norm();
    if (sn < 1e-12) return 2.0 * v;
    const double angle = 2.0 * std::atan2(sn, q.w());
    return v * (angle / sn);
}

double angle_between(const Quat& q_a, const Quat& q_b) { return rotv_from_quat(q_a.conjugate() * q_b).norm(); }

Eigen::Vector4d quat_derivative(const Quat& q, const Vec3& w) {
    Eigen::Vector4d d;
    d(0) = 0.5 * (-q.x() * w.x() - q.y() * w.y() - q.z() * w.z());
    d(1) = 0.5 * (q.w() * w.x() + q.y() * w.z() - q.z() * w.y());
    d(2) = 0.5 * (q.w() * w.y() - q.x() * w.z() + q.z() * w.x());
    d(3) = 0.5 * (q.w() * w.z() + q.x() * w.y() - q.y() * w.x());
    return d;
}

Eigen::Vector4d to_wxyz(const Quat& q) { return {q.w(), q.x(), q.y(), q.z()}; }
Quat from_wxyz(const Eigen::Vector4d& v) { return Quat(v(0), v(1), v(2), v(3)); }

Vec3 vtas_body(double tas, double aoa, double aos) {
    return {tas * std::cos(aoa) * std::cos(aos), tas * std::sin(aos), tas * std::sin(aoa) * std::cos(aos)};
}

AirAngles air_angles(const Vec3& v) {
    AirAngles a;
    a.tas_mps = v.norm();
    if (a.tas_mps < 1e-9) return a;
    a.aoa_rad = std::atan2(v.z(), v.x());
    a.aos_rad = std::asin(std::clamp(v.y() / a.tas_mps, -1.0, 1.0));
    return a;
}

// Euler (yaw = -aos, pitch = aoa, bank = 0) is the body->wind rotation; its transpose maps wind into body:
// R_bw * (V, 0, 0) == vtas_body(V, aoa, aos).
Mat3 dcm_body_from_wind(double aoa, double aos) { return dcm_from_euler({-aos, aoa, 0.0}).transpose(); }

}  // namespace gdnav::core::math
