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
    const auto& q = m.q_nb();
    e.q_nb = Quat(q[0], q[1], q[2], q[3]);
    e.euler_rad = v3(m.euler_rad());
    e.w_nb_b_rps = v3(m.w_nb_b_rps());
    e.gyr_bias_rps = v3(m.gyr_bias_rps());
    e.mag_bias_nT = v3(m.mag_bias_nT());
    e.b_dev_n_nT = v3(m.b_dev_n_nT());
    e.att_sigma_rad = v3(m.att_sigma_rad());
    return e;
}

PositionEstimate from_msg(const msg::PositionEstimate& m) {
    PositionEstimate e;
    e.stamp = {m.stamp().step(), m.stamp().t_s()};
    e.lon_rad = m.lon_rad();
    e.lat_rad = m.lat_rad();
    e.h_m = m.h_m();
    e.v_n_mps = v3(m.v_n_mps());
    e.wind_n_mps = v3(m.wind_n_mps());
    e.Hp_m = m.Hp_m();
    e.dp_Pa = m.dp_Pa();
    e.dT_K = m.dT_K();
    e.acc_err_b_mps2 = v3(m.acc_err_b_mps2());
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
    m.q_nb({e.q_nb.w(), e.q_nb.x(), e.q_nb.y(), e.q_nb.z()});
    m.euler_rad(a3(e.euler_rad));
    m.w_nb_b_rps(a3(e.w_nb_b_rps));
    m.gyr_bias_rps(a3(e.gyr_bias_rps));
    m.mag_bias_nT(a3(e.mag_bias_nT));
    m.b_dev_n_nT(a3(e.b_dev_n_nT));
    m.att_sigma_rad(a3(e.att_sigma_rad));
}

void to_msg(const PositionEstimate& e, msg::PositionEstimate& m) {
    m.lon_rad(e.lon_rad);
    m.lat_rad(e.lat_rad);
    m.h_m(e.h_m);
    m.v_n_mps(a3(e.v_n_mps));
    m.wind_n_mps(a3(e.wind_n_mps));
    m.Hp_m(e.Hp_m);
    m.dp_Pa(e.dp_Pa);
    m.dT_K(e.dT_K);
    m.acc_err_b_mps2(a3(e.acc_err_b_mps2));
    m.gnss_denied(e.gnss_denied);
}

}  // namespace gdnav::nav
