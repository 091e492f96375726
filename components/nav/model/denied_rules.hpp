#pragma once
// GNSS-denied reconstruction of ground velocity, wind, altitude and horizontal position (paper "Position Filter"
// and "Comparison with Other Navigation Algorithms"; docs/navigation.md "Position filter").
// Pure functions of the previous denied state and the current air data, attitude and specific-force estimates.
//
// Horizontal rules (velocity):
//   frozen_wind (baseline):  wind = wind(k-1) (frozen at the GNSS loss);  v = wind + R(q) v_tas_b
//   double_integration:      v_dot = R(q) f + g(x(k-1)) - w_en(k-1) x v(k-1) - a_cor(k-1);  v = v(k-1) + dt v_dot;
//                            wind (output only) = v - R(q) v_tas_b
//   wind_integration (paper eqs. = reference pos03B): v_dot as above;
//                            v_tas_dot_n = R(q) (v_tas_dot_b + w_nb x v_tas_b);
//                            wind = wind(k-1) + dt (v_dot - v_tas_dot_n);  v = wind + R(q) v_tas_b
// Vertical rules (altitude):
//   pressure (baseline):     H = H(Hp, dT, dp) (INSA, dp frozen at the GNSS loss);  h = R_E H / (R_E - H)
//   integration:             h = h(k-1) - dt v_D
//   airspeed_integration:    vertical wind forced to 0: v_D = [R(q) v_tas_b]_D, wind_D = 0;  h = h(k-1) - dt v_D
// Horizontal position (all rules): lon += dt v_E/((N(lat(k-1)) + h) cos lat(k-1)),  lat += dt v_N/(M(lat(k-1)) + h).
#include "nav_types.hpp"

namespace gdnav::nav::denied {

enum class HorizontalRule { kFrozenWind, kDoubleIntegration, kWindIntegration };
enum class VerticalRule { kPressure, kIntegration, kAirspeedIntegration };

// Carried from one denied step to the next.
struct DeniedState {
    double lon_rad{0.0};
    double lat_rad{0.0};
    double h_m{0.0};
    Vec3 v_n_mps{Vec3::Zero()};
    Vec3 wind_n_mps{Vec3::Zero()};
    double dp_Pa{0.0};  // frozen pressure offset
};

struct DeniedInputs {
    Quat q_nb{Quat::Identity()};
    Vec3 w_nb_b_rps{Vec3::Zero()};
    Vec3 f_b_mps2{Vec3::Zero()};  // specific force estimate of the 6-state EKF
    AirDataEstimate air;
};

// Airspeed vector time derivative in body from (v_tas, aoa, aos) and their rates.
Vec3 vtas_dot_body(double tas, double aoa, double aos, double tas_dot, double aoa_dot, double aos_dot);
// The same derivative as a matrix: d v_tas_b / d(tas, aoa, aos), its columns vtas_dot_body of unit rates.
Eigen::Matrix3d vtas_jacobian(double tas, double aoa, double aos);
// Ground acceleration in NED, paper eq. (Ana_PosFilter_xhor_double_vndot).
Vec3 ground_accel_n(const Quat& q_nb, const Vec3& f_b, double lat_rad, double h_m, const Vec3& v_n);
// Geometric altitude from pressure altitude, temperature and pressure offsets (INSA + spherical Earth).
double altitude_from_pressure(double hp_m, double dt_k, double dp_pa);

DeniedState step(const DeniedState& prev, const DeniedInputs& in, double dt_s, HorizontalRule hor, VerticalRule ver);

}  // namespace gdnav::nav::denied
