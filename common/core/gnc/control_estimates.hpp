#pragma once
// The navigation estimates the autopilot closes its loops on (navigation filter outputs, SI). Guidance's and
// control's component wrappers fill it from the estimate topics; it lives here so that neither model includes the
// other.
#include "math/rotation.hpp"

namespace gdnav::core::gnc {

struct ControlEstimates {
    double airspeed_mps{0.0};                   // air data filter: true airspeed V
    double aoa_rad{0.0};                        // air data filter: angle of attack alpha
    double aos_rad{0.0};                        // air data filter: angle of sideslip beta
    math::Quat q_nb{math::Quat::Identity()};    // attitude filter: body -> NED rotation
    math::Vec3 v_n_mps{math::Vec3::Zero()};     // position filter: ground velocity, NED
    double pressure_altitude_m{0.0};            // air data filter: Hp
    double altitude_m{0.0};                     // position filter: h
};

}  // namespace gdnav::core::gnc
namespace gdnav { namespace gnc = core::gnc; }  // the short name (docs/architecture.md, "Namespaces")

namespace gdnav::control {
using ControlEstimates = gnc::ControlEstimates;  // its name in the control model's API
}
