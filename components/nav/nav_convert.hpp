#pragma once
// Copies between the IDL topics (gdnav::msg) and the navigation models' plain structs (gdnav::nav).
#include "model/nav_types.hpp"
#include "runtime/messages.hpp"
#include "runtime/msg_eigen.hpp"

namespace gdnav::nav {

using runtime::to_array;
using runtime::to_quat;
using runtime::to_vec3;

inline ImuSample from_msg(const msg::ImuSample& m) { return {to_vec3(m.f_b_mps2()), to_vec3(m.w_b_rps())}; }
inline MagSample from_msg(const msg::MagSample& m) { return {to_vec3(m.b_b_nT())}; }
inline AirSample from_msg(const msg::AirSample& m) { return {m.tas_mps(), m.aoa_rad(), m.aos_rad()}; }
inline AtmSample from_msg(const msg::AtmSample& m) { return {m.p_Pa(), m.T_K()}; }
inline GnssSample from_msg(const msg::GnssSample& m) {
    return {m.fix_valid(), m.lon_rad(), m.lat_rad(), m.h_m(), to_vec3(m.v_n_mps())};
}

AirDataEstimate from_msg(const msg::AirDataEstimate& m);
AttitudeEstimate from_msg(const msg::AttitudeEstimate& m);
PositionEstimate from_msg(const msg::PositionEstimate& m);
void to_msg(const AirDataEstimate& e, msg::AirDataEstimate& m);
void to_msg(const AttitudeEstimate& e, msg::AttitudeEstimate& m);
void to_msg(const PositionEstimate& e, msg::PositionEstimate& m);

}  // namespace gdnav::nav
