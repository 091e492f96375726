#include "nav_synthetic.hpp"

#include "gnc/alignment.hpp"

#include <cmath>

#include "math/rotation.hpp"
#include "nav_earth.hpp"

namespace gdnav::nav::synth {

double Hp_from_H(double hg, double dt, double dp) {
    double hp = hg;
    for (int i = 0; i < 30; ++i) {
        const double f = earth::H_from_Hp(hp, dt, dp) - hg;
        const double df = 1.0 + dt / (earth::kT0_K + earth::kBetaT_Kpm * hp);  // dH/dHp
        hp -= f / df;
        if (std::abs(f) < 1e-10) break;
    }
    return hp;
}

Generator::Generator(const Scenario& sc, rnd::Stream stream)
    : sc_(sc), stream_(stream), lon_(sc.lon0_rad), lat_(sc.lat0_rad), h_(sc.h0_m), yaw_(sc.yaw0_rad) {}

Alignment Generator::alignment(rnd::Stream stream, bool exact) const {
    sensors::AlignmentErrors e;
    if (exact) e = {0.0, true, 0.0, 0.0, 0.0, 0.0};
    const Quat q = math::quat_from_euler({sc_.yaw0_rad, sc_.pitch_rad, sc_.bank_rad});
    const sensors::ImuAlignment i = sensors::align_imu(e, q, sc_.gyr_err_b_rps, sc_.acc_err_b_mps2, stream);
    const sensors::MagAlignment m = sensors::align_mag(e, sc_.mag_err_b_nT, sc_.b_dev_n_nT, stream);
    return {.q_nb = i.q_nb,
            .att_sigma_rad = i.att_sigma_rad,
            .gyr_err_rps = i.gyr_err_rps,
            .gyr_err_sigma_rps = i.gyr_err_sigma_rps,
            .acc_err_mps2 = i.acc_err_mps2,
            .acc_err_sigma_mps2 = i.acc_err_sigma_mps2,
            .mag_err_nT = m.mag_err_nT,
            .mag_err_sigma_nT = m.mag_err_sigma_nT,
            .b_dev_n_nT = m.b_dev_n_nT,
            .b_dev_sigma_nT = m.b_dev_sigma_nT};
}

Sample Generator::next() {
    Sample s;
    const double t = sc_.t0_s + static_cast<double>(k_) * sc_.dt_s;
    Truth& tr = s.truth;
    tr.t_s = t;
    double yaw = sc_.yaw0_rad + sc_.yaw_rate_rps * (t - sc_.t0_s);
    double ph = sc_.bank_rad, r = sc_.yaw_rate_rps, ph_dot = 0.0;
    if (std::isfinite(sc_.reverse_turn_at_s)) {
        // Bank b cos(pi s / T) over the roll (s = t - t_rev in [0, T]), coordinated yaw rate r0 tan(bank) / tan(b);
        // the yaw is integrated step by step (forward Euler on that rate).
        const double s_rev = t - sc_.reverse_turn_at_s;
        if (s_rev >= sc_.reverse_roll_s) {
            ph = -ph;
        } else if (s_rev >= 0.0) {
            const double a = math::kPi / sc_.reverse_roll_s;
            ph = sc_.bank_rad * std::cos(a * s_rev);
            ph_dot = -sc_.bank_rad * a * std::sin(a * s_rev);
        }
        r = sc_.bank_rad != 0.0 ? sc_.yaw_rate_rps * std::tan(ph) / std::tan(sc_.bank_rad) : sc_.yaw_rate_rps;
        yaw = yaw_;
        yaw_ += sc_.dt_s * r;
    }
    const double th = sc_.pitch_rad;
    tr.q_nb = math::quat_from_euler({yaw, th, ph});
    const Eigen::Matrix3d rnb = tr.q_nb.toRotationMatrix();
    tr.w_nb_b_rps = r * Vec3(-std::sin(th), std::sin(ph) * std::cos(th), std::cos(ph) * std::cos(th)) +
                    Vec3(ph_dot, 0.0, 0.0);
    const Vec3 vtas_b = math::vtas_body(sc_.tas_mps, sc_.aoa_rad, sc_.aos_rad);
    tr.v_n_mps = sc_.wind_n_mps + rnb * vtas_b;
    tr.lon_rad = lon_;
    tr.lat_rad = lat_;
    tr.h_m = h_;
    const Vec3 vdot_n = rnb * tr.w_nb_b_rps.cross(vtas_b);
    const Vec3 wen = earth::w_en_n(lat_, h_, tr.v_n_mps);
    const Vec3 wie = earth::w_ie_n(lat_);
    const Vec3 f_b = rnb.transpose() * (vdot_n + wen.cross(tr.v_n_mps) - earth::gravity_n(lat_, h_) +
                                        earth::a_cor_n(lat_, tr.v_n_mps));
    rnd::Stream& st = stream_;
    s.imu.w_b_rps = tr.w_nb_b_rps + rnb.transpose() * (wie + wen) + sc_.gyr_err_b_rps + sc_.gyr_sigma_rps * st.normal3();
    s.imu.f_b_mps2 = f_b + sc_.acc_err_b_mps2 + sc_.acc_sigma_mps2 * st.normal3();
    const Vec3 b_true_n = earth::magnetic_model_n(lon_, lat_) - sc_.b_dev_n_nT;
    s.mag.b_b_nT = rnb.transpose() * b_true_n + sc_.mag_err_b_nT + sc_.mag_sigma_nT * st.normal3();
    s.air.tas_mps = sc_.tas_mps + sc_.tas_sigma_mps * st.normal();
    s.air.aoa_rad = sc_.aoa_rad + sc_.angle_sigma_rad * st.normal();
    s.air.aos_rad = sc_.aos_rad + sc_.angle_sigma_rad * st.normal();
    tr.Hp_m = Hp_from_H(earth::H_from_h(h_), sc_.dT_K, sc_.dp_Pa);
    s.atm.p_Pa = earth::pressure_from_Hp(tr.Hp_m) + sc_.p_sigma_Pa * st.normal();
    s.atm.T_K = earth::kT0_K + sc_.dT_K + earth::kBetaT_Kpm * tr.Hp_m + sc_.T_sigma_K * st.normal();
    if (sc_.gnss_period_steps > 0 && k_ % static_cast<std::uint64_t>(sc_.gnss_period_steps) == 0) {
        const earth::Radii rr = earth::radii(lat_);
        const Vec3 e = st.normal3();
        s.gnss.fix_valid = true;
        s.gnss.lat_rad = lat_ + sc_.gnss_hor_sigma_m * e.x() / (rr.m_m + h_);
        s.gnss.lon_rad = lon_ + sc_.gnss_hor_sigma_m * e.y() / ((rr.n_m + h_) * std::cos(lat_));
        s.gnss.h_m = h_ + sc_.gnss_ver_sigma_m * e.z();
        s.gnss.v_n_mps = tr.v_n_mps + sc_.gnss_v_sigma_mps * st.normal3();
    }
    // Advance the position to the next step.
    const Vec3 rates = earth::geodetic_rates(lat_, h_, tr.v_n_mps);
    lon_ = math::wrap_pi(lon_ + sc_.dt_s * rates.x());
    lat_ += sc_.dt_s * rates.y();
    h_ += sc_.dt_s * rates.z();
    ++k_;
    return s;
}

}  // namespace gdnav::nav::synth
