#pragma once
// Rigid-body dynamics of the aircraft over the WGS84 Earth: the derivative function of the equations of motion.
//
// State x = (lon, lat, h, v^n, q_nb, w_ib^b, m): geodetic position, NED ground velocity, attitude (body -> NED),
// inertial body rate, mass. Inputs: controls u, low-frequency wind v_wind^n, turbulence v_turb^b, INSA offsets.
//   (lon_dot, lat_dot, h_dot) = (v_E / ((N+h) cos lat), v_N / (M+h), -v_D)
//   w_nb^b = w_ib^b - R_nb^T (w_ie^n + w_en^n)                     (attitude kinematics: q_dot = q (x) w_nb / 2)
//   v_tas^b = R_nb^T (v^n - v_wind^n) - v_turb^b  -> V, alpha, beta
//   air data: h -> H (spherical) -> Hp(H; dT, dp) -> p, T, rho
//   F^b = F_aero + (T_prop, 0, 0);  f_ib^b = F^b / m                 (true specific force at the CG)
//   v_dot^n = R_nb f^b + g_true^n - (2 w_ie^n + w_en^n) x v^n          (Coriolis + transport; centrifugal in g)
//   M^b = M_aero + F_aero x (CG(m) - CG_full) + (-P / (2 pi n), 0, 0)
//   w_dot_ib^b = I(m)^-1 [M^b - w_ib^b x (I(m) w_ib^b)]              (I_dot neglected)
//   m_dot = -c_f P
// Aerodynamic rates use w_nb^b (as the reference). Units SI, angles in rad.
#include <limits>

#include "atmosphere/insa.hpp"
#include "atmosphere/offsets_ramp.hpp"
#include "earth/gravity.hpp"
#include "earth/wgs84.hpp"
#include "flight_physics/model/aircraft_model.hpp"

namespace gdnav::physics {

using math::Mat3;
using math::Quat;
using math::Vec3;

struct Controls {
    double throttle{0.0};      // [0, 1]
    double elevator_rad{0.0};  // negative: nose up
    double aileron_rad{0.0};   // positive: right wing down
    double rudder_rad{0.0};    // positive: nose right
    friend bool operator==(const Controls&, const Controls&) = default;
};

struct PhysicsState {
    double lon_rad{0.0};
    double lat_rad{0.0};
    double h_m{0.0};
    Vec3 v_n_mps{Vec3::Zero()};
    Quat q_nb{Quat::Identity()};
    Vec3 w_ib_b_rps{Vec3::Zero()};
    double mass_kg{0.0};
};

// Everything computed at one evaluation: derivatives plus the intermediate quantities the truth output needs.
struct DynamicsEval {
    // derivatives
    Vec3 pos_rate{Vec3::Zero()};  // (lon_dot, lat_dot, h_dot)
    Vec3 v_dot_n{Vec3::Zero()};
    Vec3 w_dot_ib_b{Vec3::Zero()};
    double mass_rate_kgps{0.0};
    Vec3 w_nb_b{Vec3::Zero()};  // drives the attitude
    // intermediates
    Mat3 r_nb{Mat3::Identity()};
    math::AirAngles air{};
    atm::AirProperties atm{};
    Vec3 g_model_n{Vec3::Zero()};
    Vec3 g_true_n{Vec3::Zero()};
    Vec3 f_ib_b{Vec3::Zero()};
    Vec3 force_aero_b{Vec3::Zero()};
    Vec3 moment_b{Vec3::Zero()};
    PropulsionOutput prop{};
};

// Warm starts of the two iterative solves (pressure altitude, propeller speed); results do not depend on them
// beyond the solvers' convergence tolerance.
struct DynamicsWarmStart {
    double hp_m{std::numeric_limits<double>::quiet_NaN()};  // NaN: cold start
    double prop_rps{0.0};
    double dp_Pa{std::numeric_limits<double>::quiet_NaN()};  // pressure offset of the cached Hp_MSL
    double hp_msl_m{0.0};
};

class Dynamics {
public:
    Dynamics() = default;
    Dynamics(const AircraftModel& aircraft, const earth::EarthTruthParams& earth_truth);

    void evaluate(const PhysicsState& x, const Controls& u, const Vec3& wind_n_mps, const Vec3& turb_b_mps,
                  const atm::Offsets& offsets, DynamicsWarmStart& warm, DynamicsEval& out) const;

    [[nodiscard]] const AircraftModel& aircraft() const { return aircraft_; }
    [[nodiscard]] const earth::TrueGravity& gravity() const { return gravity_; }
    // Controls clamped to throttle [0, 1] and the surface limits of the aircraft.
    [[nodiscard]] Controls clamp(const Controls& u) const;

private:
    AircraftModel aircraft_;
    earth::TrueGravity gravity_;
};

}  // namespace gdnav::physics
