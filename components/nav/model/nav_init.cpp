#include "nav_init.hpp"

#include <cmath>

#include "math/rotation.hpp"

namespace gdnav::nav {

Quat coarse_attitude(const Vec3& f_b, const Vec3& b_b, const Vec3& b_model_n) {
    const Vec3 g = -f_b;  // gravity (down) direction in body
    const double pitch = std::atan2(-g.x(), std::hypot(g.y(), g.z()));
    const double bank = std::atan2(g.y(), g.z());
    const Vec3 b_h = math::dcm_from_euler({0.0, pitch, bank}) * b_b;  // field in the levelled heading frame
    const double yaw = math::wrap_pi(std::atan2(b_model_n.y(), b_model_n.x()) - std::atan2(b_h.y(), b_h.x()));
    return math::quat_from_euler({yaw, pitch, bank});
}

Quat draw_attitude_error(double sigma_rad, bool normalise_axis, rnd::Stream& stream) {
    const double gamma = stream.normal(0.0, sigma_rad);
    const double p1 = math::deg2rad(static_cast<double>(stream.uniform_int(-179, 180)));
    const double p2 = math::deg2rad(0.5 * static_cast<double>(stream.uniform_int(-179, 180)));
    Vec3 a(std::cos(p1) * std::cos(p2), std::sin(p2), std::sin(p1));
    if (normalise_axis) a.normalize();
    return math::quat_from_rotv(gamma * a);
}

Vec3 perturb_relative(const Vec3& truth, double rel, rnd::Stream& stream) {
    const Vec3 nu = stream.normal3();
    return truth.cwiseProduct(Vec3::Ones() + rel * nu);
}

}  // namespace gdnav::nav
