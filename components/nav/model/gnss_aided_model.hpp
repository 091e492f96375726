#pragma once
// Model of the GNSS-aided position filter (docs/navigation.md "Position filter"): a dual-rate EKF.
//
// State (12): x = [lon, lat, h, v_n (3), f_ib_b (3), E_acc (3)]   (rad, rad, m, m/s, m/s^2, m/s^2)
// State equations (q = current attitude estimate, an input):
//   lon_dot = v_E/((N+h) cos lat),  lat_dot = v_N/(M+h),  h_dot = -v_D
//   v_n_dot = R(q) f + g_model_n(lat, h) - (w_en_n + 2 w_ie_n) x v_n        (paper eq. force8_N)
//   f_dot = 0,  E_acc_dot = 0
// Jacobian A = df/dx is complete (it includes the dependence of the radii, gravity, transport and Earth rates on
//   lat, h and v_n; the reference codes only 1/((N+h)cos lat), 1/(M+h), -1, -[w_en x] and R(q)). The extra terms
//   are tiny at UAV speeds; they are kept so the Jacobian is exact (tested against numerical differentiation).
// Observations: fast (no fix):  y = f + E_acc                                   (3)
//               slow (fix):     y = [f + E_acc; v_n; lon; lat; h]               (9)
#include "filters/ekf.hpp"
#include "nav_types.hpp"

namespace gdnav::nav::aided {

constexpr int kN = 12;
constexpr int kMfast = 3;
constexpr int kMslow = 9;
constexpr int kLon = 0, kLat = 1, kH = 2, kV = 3, kF = 6, kE = 9;
constexpr int kJ = 9;  // the state Jacobian is zero outside its leading kJ x kJ block

using StateVec = filters::Vec<kN>;
using StateCov = filters::SqMat<kN>;

StateVec derivative(const StateVec& x, const Quat& q_nb);
StateCov state_jacobian(const StateVec& x, const Quat& q_nb);

filters::Vec<kMfast> observe_fast(const StateVec& x);
filters::Mat<kMfast, kN> jacobian_fast();
filters::Vec<kMslow> observe_slow(const StateVec& x);
filters::Mat<kMslow, kN> jacobian_slow();

}  // namespace gdnav::nav::aided
