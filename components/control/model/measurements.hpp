#pragma once
// The navigation estimates the autopilot closes its loops on, and the loop variables derived from them.
//
// Input ControlEstimates (navigation filter output, SI):
//   airspeed_mps, aoa_rad, aos_rad        air data filter: V, alpha, beta
//   q_nb                                  attitude filter: body -> NED rotation
//   v_n_mps                               position filter: ground velocity, NED
//   pressure_altitude_m, altitude_m       air data / position filters: Hp, h
// Output LoopMeasurements (what each loop compares with its target):
//   pitch, bank, heading                  Euler 3-2-1 of q_nb (theta, xi, psi)
//   ground_bearing                        chi = atan2(v_E, v_N)
//   air_bearing, air_path_angle, air_bank Euler 3-2-1 (chi_TAS, gamma_TAS, mu_TAS) of R_nw = R_nb R_bw,
//                                         R_bw = math::dcm_body_from_wind(alpha, beta)
//   sideslip                              beta
#include "gnc/control_estimates.hpp"
#include "math/rotation.hpp"

namespace gdnav::control {

struct LoopMeasurements {
    double airspeed_mps{0.0};
    double pitch_rad{0.0};
    double bank_rad{0.0};
    double heading_rad{0.0};
    double sideslip_rad{0.0};
    double pressure_altitude_m{0.0};
    double altitude_m{0.0};
    double ground_bearing_rad{0.0};
    double air_bearing_rad{0.0};
    double air_path_angle_rad{0.0};
    double air_bank_rad{0.0};
};

LoopMeasurements measure(const ControlEstimates& est);

}  // namespace gdnav::control
