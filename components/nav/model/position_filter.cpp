#include "position_filter.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "math/rotation.hpp"
#include "nav_earth.hpp"
#include "tuning_ranges.hpp"

namespace gdnav::nav {

using config::Range;
using namespace tuning_ranges;

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
    t.q_pos_m2 = q.get_vec3("position_ned_m2", kVariance);
    t.q_v_m2ps2 = q.get_double("v_m2ps2", kVariance);
    t.q_f_m2ps4 = q.get_double("f_m2ps4", kVariance);
    t.q_acc_err_m2ps4 = q.get_double("acc_err_m2ps4", kVariance);
    const config::Config r = tuning.child("r");
    t.r_acc_m2ps4 = r.get_double("acc_m2ps4", kPositiveVariance);
    t.gnss_v_sigma_mps = r.get_double("gnss_v_sigma_mps", kPositiveSigma);
    t.gnss_hor_sigma_m = r.get_double("gnss_hor_sigma_m", kPositiveSigma);
    t.gnss_ver_sigma_m = r.get_double("gnss_ver_sigma_m", kPositiveSigma);
    t.lowpass_time_constant_s = tuning.get_double("lowpass_time_constant_s", Range{0.0, 1000.0});
    t.gnss_loss_timeout_s = tuning.get_double("gnss_loss_timeout_s", Range{0.0, 60.0});
    const config::Config init = tuning.child("init");
    t.init_mode = init.get_choice("mode", {"measurements", "alignment"}) == "alignment" ? InitMode::kAlignment
                                                                                         : InitMode::kMeasurements;
    t.init_acc_bias_sigma_mps2 = init.child("measurements").get_double("acc_bias_sigma_mps2", Range{0.0, 1.0e3});
    const config::Config gi = tuning.child("gnss_integrity");
    t.gate_chi2_6dof = gi.get_double("gate_chi2_6dof", Range{1.0, 1.0e12});
    t.gate_max_consecutive_rejections = static_cast<int>(gi.get_int("max_consecutive_rejections", 1, 1000000));
    t.reacquire_fixes = static_cast<int>(gi.get_int("reacquire_fixes", 0, 1000));
    t.reacquire_consistency_chi2_3dof = gi.get_double("reacquire_consistency_chi2_3dof", Range{1.0, 1.0e12});
    t.reacquire_dr_bound_m = gi.get_double("reacquire_dr_bound_m", Range{0.0, 1.0e7});
    t.reacquire_dr_bound_rate_mps = gi.get_double("reacquire_dr_bound_rate_mps", Range{0.0, 1.0e4});
    t.horizontal = parse_horizontal_rule(variant);
    t.vertical = parse_vertical_rule(variant);
    t.frozen_wind_average_s = variant.get_double("frozen_wind_average_s", 0.0, Range{0.0, 1000.0});
    t.wind_from_gnss_ins = variant.get_choice("wind_at_loss", "own", {"own", "gnss_ins"}) == "gnss_ins";
    tuning.finish();
    variant.finish();
    configure(t, stream);
}

void PositionFilter::configure(const Tuning& tuning, rnd::Stream stream) {
    tun_ = tuning;
    stream_ = stream;
    monitor_ = GnssLossMonitor(tun_.gnss_loss_timeout_s);
    rej_ = {};
    reacquisitions_ = gate_accepted_ = 0;
    gate_d2_max_accepted_ = gate_d2_last_ = 0.0;
    initialized_ = false;
    gnss_ins_.reset();
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
    if (!checks::gnss_fix_ok(gnss) || !checks::imu_ok(imu) || !checks::air_estimate_ok(air) ||
        !checks::attitude_estimate_ok(att))
        throw std::invalid_argument("PositionFilter::initialize: non-finite or out-of-range input");
    x_.setZero();
    x_(aided::kLon) = math::wrap_pi(gnss.lon_rad);
    x_(aided::kLat) = gnss.lat_rad;
    x_(aided::kH) = gnss.h_m;
    x_.segment<3>(aided::kV) = gnss.v_n_mps;
    x_.segment<3>(aided::kF) = imu.f_b_mps2 - acc_err0;
    x_.segment<3>(aided::kE) = acc_err0;
    p_.setZero();
    set_fix_covariance(gnss.lat_rad, gnss.h_m);
    // f0 = f~(t0) - E_acc,0, so the errors of f0 and E_acc,0 are opposite: cov(f0, E0) = -P_E. The reference's
    // diagonal P0 drops this term; then the first steps' change of the measured specific force (a gust, a throttle
    // step) is shared between f and E_acc by their variances, and a bias error of several sigma is left in E_acc,
    // which the attitude filter turns into a tilt (and, through the magnetometer, a heading) error.
    p_.diagonal().segment<3>(aided::kF) = acc_err_sigma0.array().square() + tun_.r_acc_m2ps4;
    p_.diagonal().segment<3>(aided::kE) = acc_err_sigma0.array().square();
    const Eigen::Matrix3d cov_fe = -Eigen::Matrix3d(acc_err_sigma0.array().square().matrix().asDiagonal());
    p_.block<3, 3>(aided::kF, aided::kE) = cov_fe;
    p_.block<3, 3>(aided::kE, aided::kF) = cov_fe;
    wind_lp_ = wind_at_fix_ = wind_avg_ = wind_instant(air, att);
    dp_lp_ = dp_at_fix_ = dp_instant(air);
    monitor_.reset(t_s);
    lost_event_ = reacquired_event_ = false;
    denied_reason_ = DeniedReason::kNone;
    consecutive_rejections_ = candidate_count_ = 0;
    air_held_ = air;
    att_held_ = att;
    initialized_ = true;
    return output(k, t_s, air);
}

// Position and velocity blocks of P (zero cross terms) for a state taken from a fix: the fix variances.
void PositionFilter::set_fix_covariance(double lat_rad, double h_m) {
    const earth::Radii rr = earth::radii(lat_rad);
    const double s_lon = tun_.gnss_hor_sigma_m / ((rr.n_m + h_m) * std::cos(lat_rad));
    const double s_lat = tun_.gnss_hor_sigma_m / (rr.m_m + h_m);
    p_.topRows<6>().setZero();
    p_.leftCols<6>().setZero();
    p_.diagonal().head<3>() << s_lon * s_lon, s_lat * s_lat, tun_.gnss_ver_sigma_m * tun_.gnss_ver_sigma_m;
    p_.diagonal().segment<3>(aided::kV).setConstant(tun_.gnss_v_sigma_mps * tun_.gnss_v_sigma_mps);
}

Vec3 PositionFilter::wind_instant(const AirDataEstimate& air, const AttitudeEstimate& att) const {
    return x_.segment<3>(aided::kV) - att.q_nb * math::vtas_body(air.tas_mps, air.aoa_rad, air.aos_rad);
}

double PositionFilter::dp_instant(const AirDataEstimate& air) const {
    return earth::dp_from_H(earth::H_from_h(x_(aided::kH)), air.Hp_m, air.dT_K);
}

PositionEstimate PositionFilter::step(std::uint64_t k, double t_s, const ImuSample& imu, const GnssSample& gnss,
                                      const AirDataEstimate& air_in, const AttitudeEstimate& att_in) {
    if (!initialized_) throw std::logic_error("PositionFilter::step before initialize");
    // Input checks: a rejected estimate from another filter is replaced by the last good one.
    if (checks::air_estimate_ok(air_in)) {
        air_held_ = air_in;
    } else {
        ++rej_.air;
    }
    if (checks::attitude_estimate_ok(att_in)) {
        att_held_ = att_in;
    } else {
        ++rej_.attitude;
    }
    const AirDataEstimate& air = air_held_;
    const AttitudeEstimate& att = att_held_;
    const bool imu_good = checks::imu_ok(imu);
    if (!imu_good) ++rej_.imu;
    const bool fix = gnss.fix_valid && checks::gnss_fix_ok(gnss);
    if (gnss.fix_valid && !fix) ++rej_.gnss_invalid;
    reacquired_event_ = false;
    lost_event_ = monitor_.update(t_s, fix);
    if (lost_event_) {
        denied_reason_ = monitor_.publisher_dead() ? DeniedReason::kPublisherDead : DeniedReason::kTimeout;
        enter_denied(t_s);
    }
    if (monitor_.denied()) {
        denied_step(imu, imu_good, air, att);
        if (fix && !monitor_.publisher_dead() && tun_.reacquire_fixes > 0) reacquisition_candidate(t_s, gnss, air, att);
    } else {
        const bool accepted = aided_step(imu, imu_good, gnss, fix, air, att);
        if (!accepted && consecutive_rejections_ >= tun_.gate_max_consecutive_rejections) {
            // The fix source is untrusted: dead reckoning from the aided state of this step.
            enter_denied(t_s);
            monitor_.force_denied();
            denied_reason_ = DeniedReason::kUntrusted;
            lost_event_ = true;
        }
    }
    return output(k, t_s, air);
}

bool PositionFilter::aided_step(const ImuSample& imu, bool imu_good, const GnssSample& gnss, bool fix,
                                const AirDataEstimate& air, const AttitudeEstimate& att) {
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
    bool accepted = true;
    bool use_fix = fix;
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
        // Chi-square gate on the GNSS rows (v_n, lon, lat, h), in metres: d2 = r^T (H P H^T + R)^-1 r, 6 dof.
        // Computed aside: the update below is the same expression as without the gate.
        const filters::Mat<6, aided::kN> hg = aided::jacobian_slow().bottomRows<6>();
        filters::Vec<6> scale;
        scale << 1.0, 1.0, 1.0, re, rn, 1.0;
        const filters::Vec<6> rg = scale.cwiseProduct(r.tail<6>());
        filters::SqMat<6> sg = hg.lazyProduct(p_).lazyProduct(hg.transpose());
        sg.diagonal() += rd.tail<6>();
        sg = scale.asDiagonal() * sg * scale.asDiagonal();
        const Eigen::LLT<filters::SqMat<6>> llt(0.5 * (sg + sg.transpose()));
        const double d2 = llt.info() == Eigen::Success ? rg.dot(llt.solve(rg)) : std::numeric_limits<double>::infinity();
        gate_d2_last_ = d2;
        if (!(d2 <= tun_.gate_chi2_6dof)) {
            accepted = use_fix = false;
            ++rej_.gnss_gate;
            ++consecutive_rejections_;
        } else {
            consecutive_rejections_ = 0;
            ++gate_accepted_;
            gate_d2_max_accepted_ = std::max(gate_d2_max_accepted_, d2);
            if (imu_good) {
                filters::joseph_update_diag<aided::kN, aided::kMslow>(x_, p_, r, aided::jacobian_slow(), rd);
            } else {
                filters::joseph_update_diag<aided::kN, 6>(x_, p_, r.tail<6>().eval(), hg, rd.tail<6>().eval());
            }
        }
    }
    if (!use_fix && imu_good) {
        const filters::Vec<aided::kMfast> r = imu.f_b_mps2 - aided::observe_fast(x_);
        filters::joseph_update_diag<aided::kN, aided::kMfast>(x_, p_, r, aided::jacobian_fast(),
                                                         filters::Vec<3>::Constant(tun_.r_acc_m2ps4));
    }
    x_(aided::kLon) = math::wrap_pi(x_(aided::kLon));
    // GNSS-based wind and pressure offset (first-order low pass).
    const double a = dt / (tun_.lowpass_time_constant_s + dt);
    const Vec3 wind_now = wind_instant(air, att);
    wind_lp_ = (1.0 - a) * wind_lp_ + a * wind_now;
    dp_lp_ = (1.0 - a) * dp_lp_ + a * dp_instant(air);
    if (tun_.frozen_wind_average_s > 0.0) {  // the mean wind for the denied phase (variant frozen_wind_average_s)
        const double b = dt / (tun_.frozen_wind_average_s + dt);
        wind_avg_ = (1.0 - b) * wind_avg_ + b * wind_now;
    }
    if (use_fix) {
        wind_at_fix_ = tun_.frozen_wind_average_s > 0.0 ? wind_avg_ : wind_lp_;
        dp_at_fix_ = dp_lp_;
    }
    return accepted;
}

void PositionFilter::enter_denied(double t_s) {
    t_denied_s_ = t_s;
    candidate_count_ = 0;
    consecutive_rejections_ = 0;
    xd_ << x_.segment<3>(aided::kF), x_.segment<3>(aided::kE);
    pd_.topLeftCorner<3, 3>() = p_.block<3, 3>(aided::kF, aided::kF);
    pd_.topRightCorner<3, 3>() = p_.block<3, 3>(aided::kF, aided::kE);
    pd_.bottomLeftCorner<3, 3>() = p_.block<3, 3>(aided::kE, aided::kF);
    pd_.bottomRightCorner<3, 3>() = p_.block<3, 3>(aided::kE, aided::kE);
    ds_.lon_rad = x_(aided::kLon);
    ds_.lat_rad = x_(aided::kLat);
    ds_.h_m = x_(aided::kH);
    ds_.v_n_mps = x_.segment<3>(aided::kV);
    ds_.wind_n_mps = gnss_ins_ ? gnss_ins_->wind_n_mps : wind_at_fix_;
    ds_.dp_Pa = dp_at_fix_;
}

void PositionFilter::denied_step(const ImuSample& imu, bool imu_good, const AirDataEstimate& air,
                                 const AttitudeEstimate& att) {
    // 6-state EKF: static model (Phi = I), y = f + E_acc (no update with a rejected IMU sample).
    filters::Vec<kNd> q;
    q << Vec3::Constant(tun_.q_f_m2ps4), Vec3::Constant(tun_.q_acc_err_m2ps4);
    pd_.diagonal() += q;
    if (imu_good) {
        filters::Mat<3, kNd> h;
        h << Eigen::Matrix3d::Identity(), Eigen::Matrix3d::Identity();
        const Vec3 r = imu.f_b_mps2 - h * xd_;
        filters::joseph_update_diag<kNd, 3>(xd_, pd_, r, h, filters::Vec<3>::Constant(tun_.r_acc_m2ps4));
    }
    denied::DeniedInputs in;
    in.q_nb = att.q_nb;
    in.w_nb_b_rps = att.w_nb_b_rps;
    in.f_b_mps2 = xd_.head<3>();
    in.air = air;
    if (gnss_ins_) {
        in.air.tas_mps -= gnss_ins_->air_offsets.x();
        in.air.aoa_rad -= gnss_ins_->air_offsets.y();
        in.air.aos_rad -= gnss_ins_->air_offsets.z();
    }
    ds_ = denied::step(ds_, in, tun_.dt_s, tun_.horizontal, tun_.vertical);
}

void PositionFilter::reacquisition_candidate(double t_s, const GnssSample& gnss, const AirDataEstimate& air,
                                            const AttitudeEstimate& att) {
    // Horizontal distance between the fix and the dead-reckoned position.
    const earth::Radii rr = earth::radii(ds_.lat_rad);
    const double rn = rr.m_m + ds_.h_m, re = (rr.n_m + ds_.h_m) * std::cos(ds_.lat_rad);
    const double dist_m = std::hypot((gnss.lat_rad - ds_.lat_rad) * rn, math::wrap_pi(gnss.lon_rad - ds_.lon_rad) * re);
    const double bound_m = tun_.reacquire_dr_bound_m + tun_.reacquire_dr_bound_rate_mps * (t_s - t_denied_s_);
    if (!(dist_m <= bound_m)) {
        ++rej_.gnss_reacquire;
        candidate_count_ = 0;
        return;
    }
    const double gap_s = t_s - candidate_t_s_;
    if (candidate_count_ > 0 && gap_s <= tun_.gnss_loss_timeout_s + 1e-6) {
        // Consistency with the previous counted fix: position change minus the mean fix velocity x gap.
        const earth::Radii rc = earth::radii(gnss.lat_rad);
        const double cn = rc.m_m + gnss.h_m, ce = (rc.n_m + gnss.h_m) * std::cos(gnss.lat_rad);
        const Vec3 dpos((gnss.lat_rad - candidate_.lat_rad) * cn, math::wrap_pi(gnss.lon_rad - candidate_.lon_rad) * ce,
                        -(gnss.h_m - candidate_.h_m));
        const Vec3 e = dpos - 0.5 * gap_s * (gnss.v_n_mps + candidate_.v_n_mps);
        // Difference of two fixes: variance 2 sigma^2 per axis (+ the velocity noise over the gap).
        const double sv2 = 0.5 * gap_s * gap_s * tun_.gnss_v_sigma_mps * tun_.gnss_v_sigma_mps;
        const double vh = 2.0 * tun_.gnss_hor_sigma_m * tun_.gnss_hor_sigma_m + sv2;
        const double vv = 2.0 * tun_.gnss_ver_sigma_m * tun_.gnss_ver_sigma_m + sv2;
        const double d2 = (e.x() * e.x() + e.y() * e.y()) / vh + e.z() * e.z() / vv;
        if (d2 <= tun_.reacquire_consistency_chi2_3dof) {
            ++candidate_count_;
        } else {
            ++rej_.gnss_reacquire;
            candidate_count_ = 1;  // a new sequence starts at this fix
        }
    } else {
        candidate_count_ = 1;
    }
    candidate_ = gnss;
    candidate_t_s_ = t_s;
    if (candidate_count_ >= tun_.reacquire_fixes) reacquire(t_s, gnss, air, att);
}

void PositionFilter::reacquire(double t_s, const GnssSample& gnss, const AirDataEstimate& air,
                               const AttitudeEstimate& att) {
    // Aided state from the fix (position, velocity) and the denied EKF (f, E_acc and their covariance).
    x_(aided::kLon) = math::wrap_pi(gnss.lon_rad);
    x_(aided::kLat) = gnss.lat_rad;
    x_(aided::kH) = gnss.h_m;
    x_.segment<3>(aided::kV) = gnss.v_n_mps;
    x_.segment<3>(aided::kF) = xd_.head<3>();
    x_.segment<3>(aided::kE) = xd_.tail<3>();
    p_.setZero();
    p_.block<3, 3>(aided::kF, aided::kF) = pd_.topLeftCorner<3, 3>();
    p_.block<3, 3>(aided::kF, aided::kE) = pd_.topRightCorner<3, 3>();
    p_.block<3, 3>(aided::kE, aided::kF) = pd_.bottomLeftCorner<3, 3>();
    p_.block<3, 3>(aided::kE, aided::kE) = pd_.bottomRightCorner<3, 3>();
    set_fix_covariance(gnss.lat_rad, gnss.h_m);
    wind_lp_ = wind_at_fix_ = wind_avg_ = wind_instant(air, att);
    dp_lp_ = dp_at_fix_ = dp_instant(air);
    monitor_.reacquire(t_s);
    denied_reason_ = DeniedReason::kNone;
    consecutive_rejections_ = candidate_count_ = 0;
    reacquired_event_ = true;
    ++reacquisitions_;
}

PositionEstimate PositionFilter::output(std::uint64_t k, double t_s, const AirDataEstimate& air) const {
    PositionEstimate e;
    e.stamp = {k, t_s};
    e.Hp_m = air.Hp_m;
    e.dT_K = air.dT_K;
    e.gnss_denied = monitor_.denied();
    e.gnss_lost_event = lost_event_;
    e.gnss_reacquired_event = reacquired_event_;
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
