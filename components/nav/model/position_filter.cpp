#include "position_filter.hpp"

#include <cmath>
#include <stdexcept>

#include "math/rotation.hpp"
#include "nav_earth.hpp"

namespace gdnav::nav {

using config::Range;

denied::HorizontalRule parse_horizontal_rule(const config::Config& v) {
    const std::string s = v.get_choice("horizontal", {"frozen_wind", "double_integration", "wind_integration"});
    if (s == "double_integration") return denied::HorizontalRule::kDoubleIntegration;
    if (s == "wind_integration") return denied::HorizontalRule::kWindIntegration;
    return denied::HorizontalRule::kFrozenWind;
}

denied::VerticalRule parse_vertical_rule(const config::Config& v) {
    const std::string s = v.get_choice("vertical", {"pressure", "integration", "airspeed_integration"});
    if (s == "integration") return denied::VerticalRule::kIntegration;
    if (s == "airspeed_integration") return denied::VerticalRule::kAirspeedIntegration;
    return denied::VerticalRule::kPressure;
}

void PositionFilter::configure(const config::Config& tuning, const config::Config& variant, rnd::Stream stream) {
    Tuning t;
    t.dt_s = tuning.get_double("dt_s", Range{1e-4, 1.0});
    t.transition_order = static_cast<int>(tuning.get_int("transition_order", 1, 4));
    const config::Config q = tuning.child("q_per_step");
    t.q_pos_m2 = q.get_vec3("position_ned_m2", Range::nonneg());
    t.q_v_m2ps2 = q.get_double("v_m2ps2", Range::nonneg());
    t.q_f_m2ps4 = q.get_double("f_m2ps4", Range::nonneg());
    t.q_acc_err_m2ps4 = q.get_double("acc_err_m2ps4", Range::nonneg());
    const config::Config r = tuning.child("r");
    t.r_acc_m2ps4 = r.get_double("acc_m2ps4", Range::positive());
    t.gnss_v_sigma_mps = r.get_double("gnss_v_sigma_mps", Range::positive());
    t.gnss_hor_sigma_m = r.get_double("gnss_hor_sigma_m", Range::positive());
    t.gnss_ver_sigma_m = r.get_double("gnss_ver_sigma_m", Range::positive());
    t.lowpass_time_constant_s = tuning.get_double("lowpass_time_constant_s", Range{0.0, 1000.0});
    t.gnss_loss_timeout_s = tuning.get_double("gnss_loss_timeout_s", Range{0.0, 60.0});
    const config::Config init = tuning.child("init");
    t.init_mode = init.get_choice("mode", {"measurements", "alignment"}) == "alignment" ? InitMode::kAlignment
                                                                                         : InitMode::kMeasurements;
    t.init_acc_bias_sigma_mps2 = init.child("measurements").get_double("acc_bias_sigma_mps2", Range::nonneg());
    t.horizontal = parse_horizontal_rule(variant);
    t.vertical = parse_vertical_rule(variant);
    tuning.finish();
    variant.finish();
    configure(t, stream);
}

void PositionFilter::configure(const Tuning& tuning, rnd::Stream stream) {
    tun_ = tuning;
    stream_ = stream;
    monitor_ = GnssLossMonitor(tun_.gnss_loss_timeout_s);
    initialized_ = false;
}

PositionEstimate PositionFilter::initialize(std::uint64_t k, double t_s, const ImuSample& imu, const GnssSample& gnss,
                                            const AirDataEstimate& air, const AttitudeEstimate& att,
                                            const Alignment* align) {
    if (tun_.init_mode == InitMode::kAlignment) {
        if (align == nullptr || !align->valid())
            throw std::invalid_argument("position init.mode alignment needs the alignment published by the sensors");
        return initialize(k, t_s, imu, gnss, air, att, align->acc_err_mps2, align->acc_err_sigma_mps2);
    }
    return initialize(k, t_s, imu, gnss, air, att, Vec3::Zero(), Vec3::Constant(tun_.init_acc_bias_sigma_mps2));
}

PositionEstimate PositionFilter::initialize(std::uint64_t k, double t_s, const ImuSample& imu, const GnssSample& gnss,
                                            const AirDataEstimate& air, const AttitudeEstimate& att,
                                            const Vec3& acc_err0, const Vec3& acc_err_sigma0) {
    if (!gnss.fix_valid) throw std::invalid_argument("PositionFilter::initialize needs a valid GNSS fix");
    x_.setZero();
    x_(aided::kLon) = math::wrap_pi(gnss.lon_rad);
    x_(aided::kLat) = gnss.lat_rad;
    x_(aided::kH) = gnss.h_m;
    x_.segment<3>(aided::kV) = gnss.v_n_mps;
    x_.segment<3>(aided::kF) = imu.f_b_mps2 - acc_err0;
    x_.segment<3>(aided::kE) = acc_err0;
    const earth::Radii rr = earth::radii(gnss.lat_rad);
    const double s_lon = tun_.gnss_hor_sigma_m / ((rr.n_m + gnss.h_m) * std::cos(gnss.lat_rad));
    const double s_lat = tun_.gnss_hor_sigma_m / (rr.m_m + gnss.h_m);
    p_.setZero();
    p_.diagonal().head<3>() << s_lon * s_lon, s_lat * s_lat, tun_.gnss_ver_sigma_m * tun_.gnss_ver_sigma_m;
    p_.diagonal().segment<3>(aided::kV).setConstant(tun_.gnss_v_sigma_mps * tun_.gnss_v_sigma_mps);
    // f0 = f~(t0) - E_acc,0, so the errors of f0 and E_acc,0 are opposite: cov(f0, E0) = -P_E. The reference's
    // diagonal P0 drops this term; then the first steps' change of the measured specific force (a gust, a throttle
    // step) is shared between f and E_acc by their variances, and a bias error of several sigma is left in E_acc,
    // which the attitude filter turns into a tilt (and, through the magnetometer, a heading) error.
    p_.diagonal().segment<3>(aided::kF) = acc_err_sigma0.array().square() + tun_.r_acc_m2ps4;
    p_.diagonal().segment<3>(aided::kE) = acc_err_sigma0.array().square();
    const Eigen::Matrix3d cov_fe = -Eigen::Matrix3d(acc_err_sigma0.array().square().matrix().asDiagonal());
    p_.block<3, 3>(aided::kF, aided::kE) = cov_fe;
    p_.block<3, 3>(aided::kE, aided::kF) = cov_fe;
    wind_lp_ = wind_at_fix_ = wind_instant(air, att);
    dp_lp_ = dp_at_fix_ = dp_instant(air);
    monitor_.reset(t_s);
    lost_event_ = false;
    initialized_ = true;
    return output(k, t_s, air);
}

Vec3 PositionFilter::wind_instant(const AirDataEstimate& air, const AttitudeEstimate& att) const {
    return x_.segment<3>(aided::kV) - att.q_nb * math::vtas_body(air.tas_mps, air.aoa_rad, air.aos_rad);
}

double PositionFilter::dp_instant(const AirDataEstimate& air) const {
    return earth::dp_from_H(earth::H_from_h(x_(aided::kH)), air.Hp_m, air.dT_K);
}

PositionEstimate PositionFilter::step(std::uint64_t k, double t_s, const ImuSample& imu, const GnssSample& gnss,
                                      const AirDataEstimate& air, const AttitudeEstimate& att) {
    if (!initialized_) throw std::logic_error("PositionFilter::step before initialize");
    const bool fix = gnss.fix_valid && std::isfinite(gnss.lon_rad) && std::isfinite(gnss.lat_rad) &&
                     std::isfinite(gnss.h_m) && gnss.v_n_mps.allFinite();
    lost_event_ = monitor_.update(t_s, fix);
    if (lost_event_) enter_denied();
    if (monitor_.denied()) {
        denied_step(imu, air, att);
    } else {
        aided_step(imu, gnss, fix, air, att);
    }
    return output(k, t_s, air);
}

void PositionFilter::aided_step(const ImuSample& imu, const GnssSample& gnss, bool fix, const AirDataEstimate& air,
                                const AttitudeEstimate& att) {
    const double dt = tun_.dt_s;
    // Propagate with the current attitude estimate.
    const filters::SqMat<aided::kJ> phi = filters::transition_matrix<aided::kJ>(
        aided::state_jacobian(x_, att.q_nb).topLeftCorner<aided::kJ, aided::kJ>(), dt, tun_.transition_order);
    x_ += dt * aided::derivative(x_, att.q_nb);
    aided::StateVec q = aided::StateVec::Zero();
    const earth::Radii rr = earth::radii(x_(aided::kLat));
    const double rn = rr.m_m + x_(aided::kH), re = (rr.n_m + x_(aided::kH)) * std::cos(x_(aided::kLat));
    q.head<3>() << tun_.q_pos_m2.y() / (re * re), tun_.q_pos_m2.x() / (rn * rn), tun_.q_pos_m2.z();
    q.segment<3>(aided::kV).setConstant(tun_.q_v_m2ps2);
    q.segment<3>(aided::kF).setConstant(tun_.q_f_m2ps4);
    q.segment<3>(aided::kE).setConstant(tun_.q_acc_err_m2ps4);
    filters::propagate_covariance_leading_diag<aided::kN, aided::kJ>(p_, phi, q);
    // Update: fast (accelerometer) or slow (accelerometer + GNSS).
    if (fix) {
        filters::Vec<aided::kMslow> y;
        y << imu.f_b_mps2, gnss.v_n_mps, gnss.lon_rad, gnss.lat_rad, gnss.h_m;
        filters::Vec<aided::kMslow> r = y - aided::observe_slow(x_);
        r(6) = math::wrap_pi(r(6));
        filters::Vec<aided::kMslow> rd;
        const double sv = tun_.gnss_v_sigma_mps, sh = tun_.gnss_hor_sigma_m;
        rd << Eigen::Vector3d::Constant(tun_.r_acc_m2ps4), Eigen::Vector3d::Constant(sv * sv),
            (sh / re) * (sh / re), (sh / rn) * (sh / rn), tun_.gnss_ver_sigma_m * tun_.gnss_ver_sigma_m;
        filters::joseph_update_diag<aided::kN, aided::kMslow>(x_, p_, r, aided::jacobian_slow(), rd);
    } else {
        const filters::Vec<aided::kMfast> r = imu.f_b_mps2 - aided::observe_fast(x_);
        filters::joseph_update_diag<aided::kN, aided::kMfast>(x_, p_, r, aided::jacobian_fast(),
                                                         filters::Vec<3>::Constant(tun_.r_acc_m2ps4));
    }
    x_(aided::kLon) = math::wrap_pi(x_(aided::kLon));
    // GNSS-based wind and pressure offset (first-order low pass).
    const double a = dt / (tun_.lowpass_time_constant_s + dt);
    wind_lp_ = (1.0 - a) * wind_lp_ + a * wind_instant(air, att);
    dp_lp_ = (1.0 - a) * dp_lp_ + a * dp_instant(air);
    if (fix) {
        wind_at_fix_ = wind_lp_;
        dp_at_fix_ = dp_lp_;
    }
}

void PositionFilter::enter_denied() {
    xd_ << x_.segment<3>(aided::kF), x_.segment<3>(aided::kE);
    pd_.topLeftCorner<3, 3>() = p_.block<3, 3>(aided::kF, aided::kF);
    pd_.topRightCorner<3, 3>() = p_.block<3, 3>(aided::kF, aided::kE);
    pd_.bottomLeftCorner<3, 3>() = p_.block<3, 3>(aided::kE, aided::kF);
    pd_.bottomRightCorner<3, 3>() = p_.block<3, 3>(aided::kE, aided::kE);
    ds_.lon_rad = x_(aided::kLon);
    ds_.lat_rad = x_(aided::kLat);
    ds_.h_m = x_(aided::kH);
    ds_.v_n_mps = x_.segment<3>(aided::kV);
    ds_.wind_n_mps = wind_at_fix_;
    ds_.dp_Pa = dp_at_fix_;
}

void PositionFilter::denied_step(const ImuSample& imu, const AirDataEstimate& air, const AttitudeEstimate& att) {
    // 6-state EKF: static model (Phi = I), y = f + E_acc.
    filters::Vec<kNd> q;
    q << Vec3::Constant(tun_.q_f_m2ps4), Vec3::Constant(tun_.q_acc_err_m2ps4);
    pd_.diagonal() += q;
    filters::Mat<3, kNd> h;
    h << Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Identity();
    const Vec3 r = imu.f_b_mps2 - h * xd_;
    filters::joseph_update_diag<kNd, 3>(xd_, pd_, r, h, filters::Vec<3>::Constant(tun_.r_acc_m2ps4));
    denied::DeniedInputs in;
    in.q_nb = att.q_nb;
    in.w_nb_b_rps = att.w_nb_b_rps;
    in.f_b_mps2 = xd_.head<3>();
    in.air = air;
    ds_ = denied::step(ds_, in, tun_.dt_s, tun_.horizontal, tun_.vertical);
}

PositionEstimate PositionFilter::output(std::uint64_t k, double t_s, const AirDataEstimate& air) const {
    PositionEstimate e;
    e.stamp = {k, t_s};
    e.Hp_m = air.Hp_m;
    e.dT_K = air.dT_K;
    e.gnss_denied = monitor_.denied();
    e.gnss_lost_event = lost_event_;
    if (monitor_.denied()) {
        e.lon_rad = ds_.lon_rad;
        e.lat_rad = ds_.lat_rad;
        e.h_m = ds_.h_m;
        e.v_n_mps = ds_.v_n_mps;
        e.wind_n_mps = ds_.wind_n_mps;
        e.dp_Pa = ds_.dp_Pa;
        e.f_b_mps2 = xd_.head<3>();
        e.acc_err_b_mps2 = xd_.tail<3>();
    } else {
        e.lon_rad = x_(aided::kLon);
        e.lat_rad = x_(aided::kLat);
        e.h_m = x_(aided::kH);
        e.v_n_mps = x_.segment<3>(aided::kV);
        e.wind_n_mps = wind_lp_;
        e.dp_Pa = dp_lp_;
        e.f_b_mps2 = x_.segment<3>(aided::kF);
        e.acc_err_b_mps2 = x_.segment<3>(aided::kE);
    }
    return e;
}

}  // namespace gdnav::nav
