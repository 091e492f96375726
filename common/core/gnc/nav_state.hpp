#pragma once
// The navigation estimates guidance evaluates its triggers on (docs/guidance-control.md, "Guidance"). The component
// wrappers of guidance fill it from the estimate topics; it lives here so that no component includes another's model.
#include "math/rotation.hpp"

namespace gdnav::core::gnc {

// The navigation estimates guidance needs (all from the navigation filter output, SI units).
struct NavState {
    double airspeed_mps{0.0};         // estimated true airspeed V
    double pressure_altitude_m{0.0};  // estimated pressure altitude Hp
    double altitude_m{0.0};           // estimated geometric altitude h
    double ground_bearing_rad{0.0};   // chi = atan2(v_E, v_N) of the estimated ground velocity
    double heading_rad{0.0};          // psi, yaw of the estimated body attitude
    double path_angle_rad{0.0};       // gamma = atan2(-v_D, |v_NE|) of the estimated ground velocity
};

// Builds NavState from the estimated ground velocity v_n (NED, m/s) and body attitude q_nb (body -> NED).
NavState make_nav_state(double airspeed_mps, double pressure_altitude_m, double altitude_m, const math::Vec3& v_n_mps,
                        const math::Quat& q_nb);

}  // namespace gdnav::core::gnc
namespace gdnav { namespace gnc = core::gnc; }  // the short name (docs/architecture.md, "Namespaces")

namespace gdnav::guidance {  // their names in the guidance model's API, as before
using gnc::make_nav_state;
using gnc::NavState;
}  // namespace gdnav::guidance
