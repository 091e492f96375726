#include "gnc/nav_state.hpp"

#include <cmath>

namespace gdnav::core::gnc {

NavState make_nav_state(double airspeed_mps, double pressure_altitude_m, double altitude_m, const math::Vec3& v_n_mps,
                        const math::Quat& q_nb) {
    NavState s;
    s.airspeed_mps = airspeed_mps;
    s.pressure_altitude_m = pressure_altitude_m;
    s.altitude_m = altitude_m;
    s.ground_bearing_rad = std::atan2(v_n_mps.y(), v_n_mps.x());
    s.path_angle_rad = std::atan2(-v_n_mps.z(), std::hypot(v_n_mps.x(), v_n_mps.y()));
    s.heading_rad = math::euler_from_quat(q_nb).yaw_rad;
    return s;
}

}  // namespace gdnav::core::gnc
