#pragma once
// Copies between the IDL topics (gdnav::msg) and the navigation models' plain structs (gdnav::nav).
#include "model/nav_types.hpp"
#include "msgs/messages.hpp"
#include "framework/msg_eigen.hpp"

namespace gdnav::nav {

using framework::to_array;
using framework::to_quat;
using framework::to_vec3;

inline ImuSample from_msg(const msg::ImuSample& m) { return {to_vec3(m.f_b_mps2()), to_vec3(m.w_b_rps())}; }
inline MagSample from_msg(const msg::MagSample& m) { return {to_vec3(m.b_b_nT())}; }
// The alignment published with the IMU (attitude, E_gyr, E_acc) and magnetometer (E_mag, B_dev) samples; without
// a magnetometer sample the magnetic fields stay zero.
inline Alignment alignment_from_msg(const msg::ImuSample& i, const msg::MagSample* mag = nullptr) {
    Alignment a;
    a.q_nb = framework::to_quat(i.align_q_nb());
    a.att_sigma_rad = i.align_att_sigma_rad();
    a.gyr_err_rps = to_vec3(i.align_gyr_err_rps());
    a.gyr_err_sigma_rps = to_vec3(i.align_gyr_err_sigma_rps());
    a.acc_err_mps2 = to_vec3(i.align_acc_err_mps2());
    a.acc_err_sigma_mps2 = to_vec3(i.align_acc_err_sigma_mps2());
    if (mag != nullptr) {
        a.mag_err_nT = to_vec3(mag->align_mag_err_nT());
        a.mag_err_sigma_nT = to_vec3(mag->align_mag_err_sigma_nT());
        a.b_dev_n_nT = to_vec3(mag->align_b_dev_n_nT());
        a.b_dev_sigma_nT = to_vec3(mag->align_b_dev_sigma_nT());
    }
    return a;
}
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
