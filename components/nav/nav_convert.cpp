#include "nav_convert.hpp"

namespace gdnav::nav {

AirDataEstimate from_msg(const msg::AirDataEstimate& m) {
    AirDataEstimate e;
    e.stamp = {m.stamp().step(), m.stamp().t_s()};
    e.tas_mps = m.tas_mps();
    e.aoa_rad = m.aoa_rad();
    e.aos_rad = m.aos_rad();
    e.dT_K = m.dT_K();
    e.Hp_m = m.Hp_m();
    e.T_K = m.T_K();
    e.roc_mps = m.roc_mps();
    e.tas_dot_mps2 = m.tas_dot_mps2();
    e.aoa_dot_rps = m.aoa_dot_rps();
    e.aos_dot_rps = m.aos_dot_rps();
    return e;
}

AttitudeEstimate from_msg(const msg::AttitudeEstimate& m) {
    AttitudeEstimate e;
    e.stamp = {m.stamp().step(), m.stamp().t_s()};
    e.q_nb = to_quat(m.q_nb());
    e.euler_rad = to_vec3(m.euler_rad());
    e.w_nb_b_rps = to_vec3(m.w_nb_b_rps());
    e.gyr_bias_rps = to_vec3(m.gyr_bias_rps());
    e.mag_bias_nT = to_vec3(m.mag_bias_nT());
    e.b_dev_n_nT = to_vec3(m.b_dev_n_nT());
    e.att_sigma_rad = to_vec3(m.att_sigma_rad());
    return e;
}

PositionEstimate from_msg(const msg::PositionEstimate& m) {
    PositionEstimate e;
    e.stamp = {m.stamp().step(), m.stamp().t_s()};
    e.lon_rad = m.lon_rad();
    e.lat_rad = m.lat_rad();
    e.h_m = m.h_m();
    e.v_n_mps = to_vec3(m.v_n_mps());
    e.wind_n_mps = to_vec3(m.wind_n_mps());
    e.Hp_m = m.Hp_m();
    e.dp_Pa = m.dp_Pa();
    e.dT_K = m.dT_K();
    e.acc_err_b_mps2 = to_vec3(m.acc_err_b_mps2());
    e.gnss_denied = m.gnss_denied();
    return e;
}

void to_msg(const AirDataEstimate& e, msg::AirDataEstimate& m) {
    m.tas_mps(e.tas_mps);
    m.aoa_rad(e.aoa_rad);
    m.aos_rad(e.aos_rad);
    m.dT_K(e.dT_K);
    m.Hp_m(e.Hp_m);
    m.T_K(e.T_K);
    m.roc_mps(e.roc_mps);
    m.tas_dot_mps2(e.tas_dot_mps2);
    m.aoa_dot_rps(e.aoa_dot_rps);
    m.aos_dot_rps(e.aos_dot_rps);
}

void to_msg(const AttitudeEstimate& e, msg::AttitudeEstimate& m) {
    m.q_nb(to_array(e.q_nb));
    m.euler_rad(to_array(e.euler_rad));
    m.w_nb_b_rps(to_array(e.w_nb_b_rps));
    m.gyr_bias_rps(to_array(e.gyr_bias_rps));
    m.mag_bias_nT(to_array(e.mag_bias_nT));
    m.b_dev_n_nT(to_array(e.b_dev_n_nT));
    m.att_sigma_rad(to_array(e.att_sigma_rad));
}

void to_msg(const PositionEstimate& e, msg::PositionEstimate& m) {
    m.lon_rad(e.lon_rad);
    m.lat_rad(e.lat_rad);
    m.h_m(e.h_m);
    m.v_n_mps(to_array(e.v_n_mps));
    m.wind_n_mps(to_array(e.wind_n_mps));
    m.Hp_m(e.Hp_m);
    m.dp_Pa(e.dp_Pa);
    m.dT_K(e.dT_K);
    m.acc_err_b_mps2(to_array(e.acc_err_b_mps2));
    m.gnss_denied(e.gnss_denied);
}

}  // namespace gdnav::nav
