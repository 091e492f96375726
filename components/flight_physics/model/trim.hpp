#pragma once
// Steady, straight, wings-level trim (reference sections 4.4 and 5.5).
//
// Given latitude/longitude, pressure altitude Hp, true airspeed V, ground-track bearing chi, mass, wind and INSA
// offsets, find x = (alpha, beta, throttle, elevator, aileron, rudder) such that, with bank = 0, pitch = alpha
// (level flight relative to the air mass), w_nb = 0 and heading psi chosen so that the ground track equals chi,
//   R_nb^T v_dot^n = 0 and w_dot_ib^b = 0
// (full 6-DOF balance of the Dynamics derivative function, turbulence off). The lateral unknowns balance the
// propeller torque. Newton iteration with a central-difference Jacobian, to |residual| < 1e-10.
// Throws std::runtime_error when it does not converge or when the trim lies outside the control limits.
#include "flight_physics/model/dynamics.hpp"

namespace gdnav::physics {

struct TrimRequest {
    double lat_rad{0.0};
    double lon_rad{0.0};
    double Hp_m{0.0};
    double tas_mps{0.0};
    double bearing_rad{0.0};  // ground-track bearing chi
    double mass_kg{0.0};
    Vec3 wind_n_mps{Vec3::Zero()};
    atm::Offsets offsets{};
};

struct TrimResult {
    double aoa_rad{0.0};
    double aos_rad{0.0};
    math::Euler euler{};  // yaw, pitch (= aoa), bank (= 0)
    Controls controls{};
    PhysicsState state{};  // state in trim (no turbulence)
    double residual{0.0};  // max |component| of the residual at the solution
    int iterations{0};
    DynamicsEval eval{};  // evaluation at the trim point (thrust, power, speed, ...)
};

TrimResult trim_level_flight(const Dynamics& dynamics, const TrimRequest& request);

}  // namespace gdnav::physics
