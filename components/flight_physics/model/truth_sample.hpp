#pragma once
// The true state and environment at one instant: every field of the IDL `Truth` topic (idl/gdnav.idl), plus a few
// propulsion outputs. Frames and units as in the IDL: n = NED, b = body; SI, angles in rad.
#include "flight_physics/model/dynamics.hpp"

namespace gdnav::physics {

struct TruthSample {
    double t_s{0.0};
    // position and velocity
    double lon_rad{0.0};
    double lat_rad{0.0};
    double h_m{0.0};             // above the WGS84 ellipsoid
    Vec3 v_n_mps{Vec3::Zero()};  // ground velocity
    // attitude and rates
    Quat q_nb{Quat::Identity()};  // body -> NED (IDL order w, x, y, z: math::to_wxyz)
    math::Euler euler{};          // yaw, pitch, bank
    Vec3 w_ib_b_rps{Vec3::Zero()};
    Vec3 w_nb_b_rps{Vec3::Zero()};
    Vec3 dw_ib_b_rps2{Vec3::Zero()};
    Vec3 f_ib_b_mps2{Vec3::Zero()};  // true specific force at the CG: (aero + thrust) / mass
    // air data
    double tas_mps{0.0};
    double aoa_rad{0.0};
    double aos_rad{0.0};
    Vec3 wind_n_mps{Vec3::Zero()};  // low-frequency wind (towards its bearing)
    Vec3 turb_b_mps{Vec3::Zero()};  // turbulence velocity in body axes
    // atmosphere
    double dT_K{0.0};
    double dp_Pa{0.0};
    double Hp_m{0.0};
    double H_m{0.0};
    double p_Pa{0.0};
    double T_K{0.0};
    double rho_kgpm3{0.0};
    // Earth fields
    Vec3 g_n_mps2{Vec3::Zero()};        // true gravity
    Vec3 g_model_n_mps2{Vec3::Zero()};  // normal gravity
    Vec3 b_n_nT{Vec3::Zero()};          // true magnetic field
    Vec3 b_model_n_nT{Vec3::Zero()};    // model magnetic field
    // aircraft
    double mass_kg{0.0};
    Controls controls{};  // applied (clamped) controls
    // propulsion (not on the topic)
    double thrust_N{0.0};
    double power_W{0.0};
    double prop_speed_rps{0.0};
};

}  // namespace gdnav::physics
