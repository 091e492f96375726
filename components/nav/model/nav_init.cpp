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

}  // namespace gdnav::nav
