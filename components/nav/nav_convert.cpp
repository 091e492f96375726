#include "nav_convert.hpp"

#include <type_traits>

namespace gdnav::nav {

namespace {

void assign(double& to, double from) { to = from; }
void assign(bool& to, bool from) { to = from; }
void assign(math::Vec3& to, const std::array<double, 3>& from) { to = to_vec3(from); }
void assign(math::Quat& to, const std::array<double, 4>& from) { to = to_quat(from); }
void assign(std::array<double, 3>& to, const math::Vec3& from) { to = to_array(from); }
void assign(std::array<double, 4>& to, const math::Quat& from) { to = to_array(from); }

struct FromMsg {
    template <class E, class M>
    void operator()(E& e, const M& m) const { assign(e, m); }
};
struct ToMsg {
    template <class E, class M>
    void operator()(const E& e, M& m) const { assign(m, e); }
};

// The fields an estimate shares with its topic, as pairs (model field, message field): one list serves both
// directions (`copy` is FromMsg or ToMsg). The stamp is the framework's to write.
template <class E, class M, class Copy>
void shared_fields(E& e, M& m, Copy copy) {
    using T = std::remove_const_t<E>;
    if constexpr (std::is_same_v<T, AirDataEstimate>) {
        copy(e.tas_mps, m.tas_mps());
        copy(e.aoa_rad, m.aoa_rad());
        copy(e.aos_rad, m.aos_rad());
        copy(e.dT_K, m.dT_K());
        copy(e.Hp_m, m.Hp_m());
        copy(e.T_K, m.T_K());
        copy(e.roc_mps, m.roc_mps());
        copy(e.tas_dot_mps2, m.tas_dot_mps2());
        copy(e.aoa_dot_rps, m.aoa_dot_rps());
        copy(e.aos_dot_rps, m.aos_dot_rps());
    } else if constexpr (std::is_same_v<T, AttitudeEstimate>) {
        copy(e.q_nb, m.q_nb());
        copy(e.euler_rad, m.euler_rad());
        copy(e.w_nb_b_rps, m.w_nb_b_rps());
        copy(e.gyr_bias_rps, m.gyr_bias_rps());
        copy(e.mag_bias_nT, m.mag_bias_nT());
        copy(e.b_dev_n_nT, m.b_dev_n_nT());
        copy(e.att_sigma_rad, m.att_sigma_rad());
    } else {
        static_assert(std::is_same_v<T, PositionEstimate>);
        copy(e.lon_rad, m.lon_rad());
        copy(e.lat_rad, m.lat_rad());
        copy(e.h_m, m.h_m());
        copy(e.v_n_mps, m.v_n_mps());
        copy(e.wind_n_mps, m.wind_n_mps());
        copy(e.Hp_m, m.Hp_m());
        copy(e.dp_Pa, m.dp_Pa());
        copy(e.dT_K, m.dT_K());
        copy(e.acc_err_b_mps2, m.acc_err_b_mps2());
        copy(e.gnss_denied, m.gnss_denied());
    }
}

template <class E, class M>
E estimate_from(const M& m) {
    E e;
    e.stamp = {m.stamp().step(), m.stamp().t_s()};
    shared_fields(e, m, FromMsg{});
    return e;
}

}  // namespace

AirDataEstimate from_msg(const msg::AirDataEstimate& m) { return estimate_from<AirDataEstimate>(m); }
AttitudeEstimate from_msg(const msg::AttitudeEstimate& m) { return estimate_from<AttitudeEstimate>(m); }
PositionEstimate from_msg(const msg::PositionEstimate& m) { return estimate_from<PositionEstimate>(m); }
void to_msg(const AirDataEstimate& e, msg::AirDataEstimate& m) { shared_fields(e, m, ToMsg{}); }
void to_msg(const AttitudeEstimate& e, msg::AttitudeEstimate& m) { shared_fields(e, m, ToMsg{}); }
void to_msg(const PositionEstimate& e, msg::PositionEstimate& m) { shared_fields(e, m, ToMsg{}); }

}  // namespace gdnav::nav
