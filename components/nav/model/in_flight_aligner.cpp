// `in_flight_alignment` keys (all optional, any other key is an error; ranges and defaults):
//   start: tilt_sigma_deg [0.1, 30] (1.5), heading_sigma_deg [0.5, 60] (10), gyr_bias_sigma_dps [1e-4, 5] (0.2),
//          acc_bias_sigma_mps2 [1e-4, 5] (0.157), mag_bias_sigma_nT [1, 1e4] (530), b_dev_sigma_nT [1, 1e4] (200)
//   noise: gyr_noise_dps_rts [1e-5, 1] (4.3e-3), acc_noise_mps2_rts [1e-5, 1] (5e-4),
//          gyr_bias_walk_dps_s_rts [0, 1e-1] (2.84e-4), acc_bias_walk_mps2_s_rts [0, 1e-1] (1.4e-4),
//          mag_walk_nT_rts [0, 100] (0.1), mag_noise_nT [0.1, 1e4] (50), mag_period_steps [1, 1000] (10),
//          gnss_hor_sigma_m [0.1, 100] (8), gnss_ver_sigma_m [0.1, 100] (12), gnss_vel_sigma_mps [0.01, 10] (0.075)
//   air data, wind and M (HandOver::kNever only): wind_sigma_mps [0.01, 50] (3), wind_walk_mps_s_rts [0, 10] (0.05),
//          air_vel_sigma_mps [0.01, 20] (0.5), air_vel_sigma_denied_mps [0.01, 20] (3), air_period_steps [1, 1000]
//          (10), mag_scale_sigma [0, 0.1] (7.5e-4), mag_cross_sigma [0, 0.1] (9.16e-4), turb_sigma_mps [0, 10] (0.3),
//          turb_tau_s [0.1, 1000] (10), tas_offset_sigma_mps [0, 10] (0.333), aoa_offset_sigma_deg [0, 10] (0.333),
//          aos_offset_sigma_deg [0, 10] (0.333)
//   hand-over: tilt_sigma_max_deg [0.001, 10] (0.05), heading_sigma_max_deg [0.001, 10] (0.05), hold_s [0, 600] (10),
//              not_before_s [-1e6, 1e6] (none; a run time [s] before which it does not hand over)
#include "in_flight_aligner.hpp"

#include <algorithm>
#include <cmath>

#include "config/number_keys.hpp"
#include "denied_rules.hpp"
#include "input_checks.hpp"
#include "nav_earth.hpp"
#include "nav_init.hpp"

namespace gdnav::nav {

using config::Range;

namespace {
constexpr int kPhi = 0, kV = 3, kP = 6, kBg = 9, kBa = 12, kEm = 15, kBd = 18, kW = 21, kM = 24, kT = 33, kAd = 36;
using Mat3 = Eigen::Matrix3d;

// The section's keys (keys and ranges: this file's first comment), in the order they are read (the first bad key is
// the one reported), each with its setting and its range in the file's unit: plain, in degrees (the setting in
// radians) or a whole number of steps.
using Settings = InFlightAlignerSettings;
using Key = config::NumberKey<Settings>;
constexpr Key plain(const char* k, double Settings::*v, Range r) { return {k, v, false, r}; }
constexpr Key degrees(const char* k, double Settings::*v, Range r) { return {k, v, true, r}; }
constexpr Key steps(const char* k, int Settings::*n, Range r) { return {k, nullptr, false, r, nullptr, n}; }
constexpr std::array<Key, 32> kKeys{{
    degrees("tilt_sigma_deg", &Settings::tilt_sigma_rad, {0.1, 30.0}),
    degrees("heading_sigma_deg", &Settings::heading_sigma_rad, {0.5, 60.0}),
    degrees("gyr_bias_sigma_dps", &Settings::gyr_bias_sigma_rps, {1e-4, 5.0}),
    plain("acc_bias_sigma_mps2", &Settings::acc_bias_sigma_mps2, {1e-4, 5.0}),
    plain("mag_bias_sigma_nT", &Settings::mag_bias_sigma_nT, {1.0, 1e4}),
    plain("b_dev_sigma_nT", &Settings::b_dev_sigma_nT, {1.0, 1e4}),
    degrees("gyr_noise_dps_rts", &Settings::gyr_noise_rps_rts, {1e-5, 1.0}),
    plain("acc_noise_mps2_rts", &Settings::acc_noise_mps2_rts, {1e-5, 1.0}),
    degrees("gyr_bias_walk_dps_s_rts", &Settings::gyr_bias_walk_rps_s_rts, {0.0, 0.1}),
    plain("acc_bias_walk_mps2_s_rts", &Settings::acc_bias_walk_mps2_s_rts, {0.0, 0.1}),
    plain("mag_walk_nT_rts", &Settings::mag_walk_nT_rts, {0.0, 100.0}),
    plain("mag_noise_nT", &Settings::mag_noise_nT, {0.1, 1e4}),
    steps("mag_period_steps", &Settings::mag_period_steps, {1, 1000}),
    plain("gnss_hor_sigma_m", &Settings::gnss_hor_sigma_m, {0.1, 100.0}),
    plain("gnss_ver_sigma_m", &Settings::gnss_ver_sigma_m, {0.1, 100.0}),
    plain("gnss_vel_sigma_mps", &Settings::gnss_vel_sigma_mps, {0.01, 10.0}),
    plain("wind_sigma_mps", &Settings::wind_sigma_mps, {0.01, 50.0}),
    plain("wind_walk_mps_s_rts", &Settings::wind_walk_mps_s_rts, {0.0, 10.0}),
    plain("air_vel_sigma_mps", &Settings::air_vel_sigma_mps, {0.01, 20.0}),
    plain("air_vel_sigma_denied_mps", &Settings::air_vel_sigma_denied_mps, {0.01, 20.0}),
    steps("air_period_steps", &Settings::air_period_steps, {1, 1000}),
    plain("mag_scale_sigma", &Settings::mag_scale_sigma, {0.0, 0.1}),
    plain("mag_cross_sigma", &Settings::mag_cross_sigma, {0.0, 0.1}),
    plain("turb_sigma_mps", &Settings::turb_sigma_mps, {0.0, 10.0}),
    plain("turb_tau_s", &Settings::turb_tau_s, {0.1, 1000.0}),
    plain("tas_offset_sigma_mps", &Settings::tas_offset_sigma_mps, {0.0, 10.0}),
    degrees("aoa_offset_sigma_deg", &Settings::aoa_offset_sigma_rad, {0.0, 10.0}),
    degrees("aos_offset_sigma_deg", &Settings::aos_offset_sigma_rad, {0.0, 10.0}),
    degrees("tilt_sigma_max_deg", &Settings::tilt_sigma_max_rad, {0.001, 10.0}),
    degrees("heading_sigma_max_deg", &Settings::heading_sigma_max_rad, {0.001, 10.0}),
    plain("hold_s", &Settings::hold_s, {0.0, 600.0}),
    plain("not_before_s", &Settings::not_before_s, {-1e6, 1e6}),
}};
}  // namespace

InFlightAlignerSettings parse_in_flight_alignment(const config::Config& c, const InFlightAlignerSettings& base) {
    const InFlightAlignerSettings s = config::read_number_keys(c, kKeys, base);
    c.finish();
    return s;
}

InFlightAligner::InFlightAligner(const InFlightAlignerSettings& s, double dt_s, HandOver mode)
    : s_(s), dt_s_(dt_s), mode_(mode) {
    q_diag_.segment<3>(kPhi).setConstant(s_.gyr_noise_rps_rts * s_.gyr_noise_rps_rts * dt_s_);
    q_diag_.segment<3>(kV).setConstant(s_.acc_noise_mps2_rts * s_.acc_noise_mps2_rts * dt_s_);
    q_diag_.segment<3>(kBg).setConstant(s_.gyr_bias_walk_rps_s_rts * s_.gyr_bias_walk_rps_s_rts * dt_s_);
    q_diag_.segment<3>(kBa).setConstant(s_.acc_bias_walk_mps2_s_rts * s_.acc_bias_walk_mps2_s_rts * dt_s_);
    q_diag_.segment<6>(kEm).setConstant(s_.mag_walk_nT_rts * s_.mag_walk_nT_rts * dt_s_);
    if (mode_ == HandOver::kNever) {
        q_diag_.segment<3>(kW).setConstant(s_.wind_walk_mps_s_rts * s_.wind_walk_mps_s_rts * dt_s_);
        // The turbulence's decay is applied in propagate(); this keeps its variance at turb_sigma_mps^2.
        turb_decay_ = std::exp(-dt_s_ / s_.turb_tau_s);
        q_diag_.segment<3>(kT).setConstant(s_.turb_sigma_mps * s_.turb_sigma_mps * (1.0 - turb_decay_ * turb_decay_));
    }
}

void InFlightAligner::start(double t_s, const ImuSample& imu, const MagSample& mag, const GnssSample& fix,
                            const AirSample& air) {
    const Vec3 vtas_b = math::vtas_body(air.tas_mps, air.aoa_rad, air.aos_rad);
    q_nb_ = coarse_attitude(imu.f_b_mps2 - imu.w_b_rps.cross(vtas_b), mag.b_b_nT,
                            earth::magnetic_model_n(fix.lon_rad, fix.lat_rad));
    w_nb_b_ = imu.w_b_rps;
    e_gyr_ = e_acc_ = e_mag_ = b_dev_ = Vec3::Zero();
    start_common(t_s, fix, &air);
    // Attitude: tilt and heading sigmas on the NED side (phi is an NED-side error).
    p_.diagonal().segment<3>(kPhi) << s_.tilt_sigma_rad * s_.tilt_sigma_rad, s_.tilt_sigma_rad * s_.tilt_sigma_rad,
        s_.heading_sigma_rad * s_.heading_sigma_rad;
    p_.diagonal().segment<3>(kBg).setConstant(s_.gyr_bias_sigma_rps * s_.gyr_bias_sigma_rps);
    p_.diagonal().segment<3>(kBa).setConstant(s_.acc_bias_sigma_mps2 * s_.acc_bias_sigma_mps2);
    p_.diagonal().segment<3>(kEm).setConstant(s_.mag_bias_sigma_nT * s_.mag_bias_sigma_nT);
    p_.diagonal().segment<3>(kBd).setConstant(s_.b_dev_sigma_nT * s_.b_dev_sigma_nT);
}

void InFlightAligner::start(double t_s, const Alignment& align, const ImuSample& imu, const GnssSample& fix,
                            const AirSample* air) {
    q_nb_ = align.q_nb.normalized();
    e_gyr_ = align.gyr_err_rps;
    e_acc_ = align.acc_err_mps2;
    e_mag_ = align.mag_err_nT;
    b_dev_ = align.b_dev_n_nT;
    w_nb_b_ = imu.w_b_rps - e_gyr_;
    start_common(t_s, fix, air);
    p_.diagonal().segment<3>(kPhi).setConstant(align.att_sigma_rad * align.att_sigma_rad);
    p_.diagonal().segment<3>(kBg) = align.gyr_err_sigma_rps.array().square();
    p_.diagonal().segment<3>(kBa) = align.acc_err_sigma_mps2.array().square();
    p_.diagonal().segment<3>(kEm) = align.mag_err_sigma_nT.array().square();
    p_.diagonal().segment<3>(kBd) = align.b_dev_sigma_nT.array().square();
}

// Position, velocity and their covariance from the fix, the wind (HandOver::kNever) from the fix and the air data;
// the rest of the covariance is the caller's.
void InFlightAligner::start_common(double t_s, const GnssSample& fix, const AirSample* air) {
    v_n_ = fix.v_n_mps;
    lon_rad_ = fix.lon_rad;
    lat_rad_ = fix.lat_rad;
    h_m_ = fix.h_m;
    p_.setZero();
    p_.diagonal().segment<3>(kV).setConstant(s_.gnss_vel_sigma_mps * s_.gnss_vel_sigma_mps);
    p_.diagonal().segment<3>(kP) << s_.gnss_hor_sigma_m * s_.gnss_hor_sigma_m, s_.gnss_hor_sigma_m * s_.gnss_hor_sigma_m,
        s_.gnss_ver_sigma_m * s_.gnss_ver_sigma_m;
    wind_n_ = turb_n_ = b_air_ = Vec3::Zero();
    m_mag_.setZero();
    if (mode_ == HandOver::kNever) {
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                const double sig = i == j ? s_.mag_scale_sigma : s_.mag_cross_sigma;
                p_(kM + 3 * i + j, kM + 3 * i + j) = sig * sig;
            }
        if (air != nullptr)
            wind_n_ = v_n_ - q_nb_.toRotationMatrix() * math::vtas_body(air->tas_mps, air->aoa_rad, air->aos_rad);
        p_.diagonal().segment<3>(kW).setConstant(s_.wind_sigma_mps * s_.wind_sigma_mps);
        p_.diagonal().segment<3>(kT).setConstant(s_.turb_sigma_mps * s_.turb_sigma_mps);
        p_.diagonal().segment<3>(kAd) << s_.tas_offset_sigma_mps * s_.tas_offset_sigma_mps,
            s_.aoa_offset_sigma_rad * s_.aoa_offset_sigma_rad, s_.aos_offset_sigma_rad * s_.aos_offset_sigma_rad;
    }
    steps_ = 0;
    started_ = true;
    aligned_ = handed_over_ = criteria_met_ = false;
    t_criteria_met_s_ = t_aligned_s_ = t_handed_over_s_ = t_s;
}

bool InFlightAligner::step(double t_s, const ImuSample& imu, const MagSample& mag, const GnssSample* fix,
                           const AirSample* air) {
    if (!started_ || !running()) return false;
    propagate(imu);
    ++steps_;
    if (steps_ % static_cast<std::uint64_t>(s_.mag_period_steps) == 0) update_mag(mag);
    if (mode_ == HandOver::kNever && air != nullptr &&
        steps_ % static_cast<std::uint64_t>(s_.air_period_steps) == 0)
        update_air(*air);
    if (handed_over_ || fix == nullptr || !fix->fix_valid) return false;
    update_fix(*fix);
    if (aligned_) return false;  // latched: the criteria are not watched any more
    const bool ok = tilt_sigma_rad() <= s_.tilt_sigma_max_rad && heading_sigma_rad() <= s_.heading_sigma_max_rad;
    if (!ok) {
        criteria_met_ = false;
        return false;
    }
    if (!criteria_met_) {
        criteria_met_ = true;
        t_criteria_met_s_ = t_s;
    }
    if (t_s - t_criteria_met_s_ + 1e-9 < s_.hold_s || t_s < s_.not_before_s) return false;
    aligned_ = true;
    t_aligned_s_ = t_s;
    if (mode_ != HandOver::kAtAlignment) return false;  // it goes on until the loss, or through it
    handed_over_ = true;
    t_handed_over_s_ = t_s;
    return true;
}

void InFlightAligner::hand_over(double t_s) {
    if (!started_ || handed_over_) return;
    handed_over_ = true;
    t_handed_over_s_ = t_s;
}

void InFlightAligner::propagate(const ImuSample& imu) {
    const double dt = dt_s_;
    const Mat3 r = q_nb_.toRotationMatrix();
    const Vec3 w_ie = earth::w_ie_n(lat_rad_);
    const Vec3 w_en = earth::w_en_n(lat_rad_, h_m_, v_n_);
    const Vec3 f_n = r * (imu.f_b_mps2 - e_acc_);
    // Error dynamics at the estimate before this step's propagation.
    filters::SqMat<15> a = filters::SqMat<15>::Zero();
    a.block<3, 3>(kPhi, kBg) = -r;
    a.block<3, 3>(kV, kPhi) = -math::skew(f_n);
    a.block<3, 3>(kV, kBa) = -r;
    a.block<3, 3>(kP, kV) = Mat3::Identity();
    const filters::SqMat<15> phi = filters::transition_matrix<15>(a, dt, 2);
    if (mode_ == HandOver::kNever) {  // the turbulence's rows and columns of the transition: turb_decay_ I
        p_.middleRows<3>(kT) *= turb_decay_;
        p_.middleCols<3>(kT) *= turb_decay_;
        turb_n_ *= turb_decay_;
    }
    filters::propagate_covariance_leading_diag<kN, 15>(p_, phi, q_diag_);  // the wind: a walk, in q_diag_
    // Nominal state.
    const Vec3 w_nb = imu.w_b_rps - e_gyr_ - r.transpose() * (w_ie + w_en);
    w_nb_b_ = w_nb;
    const Vec3 v_dot = f_n + earth::gravity_n(lat_rad_, h_m_) - (2.0 * w_ie + w_en).cross(v_n_);
    const Vec3 rates = earth::geodetic_rates(lat_rad_, h_m_, v_n_);  // lon_dot, lat_dot, h_dot
    lon_rad_ = math::wrap_pi(lon_rad_ + dt * rates.x());
    lat_rad_ += dt * rates.y();
    h_m_ += dt * rates.z();
    v_n_ += dt * v_dot;
    q_nb_ = (q_nb_ * math::quat_from_rotv(w_nb * dt)).normalized();
}

void InFlightAligner::update_mag(const MagSample& mag) {
    const Mat3 rt = q_nb_.toRotationMatrix().transpose();
    const Vec3 b_n = earth::magnetic_model_n(lon_rad_, lat_rad_) - b_dev_;
    const Vec3 b_b = rt * b_n;
    const Mat3 im = Mat3::Identity() + m_mag_;
    filters::Mat<3, kN> h = filters::Mat<3, kN>::Zero();
    h.block<3, 3>(0, kPhi) = im * rt * math::skew(b_n);
    h.block<3, 3>(0, kEm) = Mat3::Identity();
    h.block<3, 3>(0, kBd) = -im * rt;
    if (mode_ == HandOver::kNever)
        for (int i = 0; i < 3; ++i) h.block<1, 3>(i, kM + 3 * i) = b_b.transpose();
    const filters::Vec<3> r = mag.b_b_nT - (im * b_b + e_mag_);
    filters::Vec<kN> dx = filters::Vec<kN>::Zero();
    const auto info = filters::joseph_update<kN, 3>(
        dx, p_, r, h, filters::SqMat<3>::Identity() * (s_.mag_noise_nT * s_.mag_noise_nT));
    if (info.ok) inject(dx);
}

void InFlightAligner::update_fix(const GnssSample& fix) {
    const earth::Radii rr = earth::radii(lat_rad_);
    filters::Vec<6> r;
    r << (fix.lat_rad - lat_rad_) * (rr.m_m + h_m_),
        math::wrap_pi(fix.lon_rad - lon_rad_) * (rr.n_m + h_m_) * std::cos(lat_rad_), -(fix.h_m - h_m_),
        fix.v_n_mps - v_n_;
    filters::Mat<6, kN> h = filters::Mat<6, kN>::Zero();
    h.block<3, 3>(0, kP) = Mat3::Identity();
    h.block<3, 3>(3, kV) = Mat3::Identity();
    filters::Vec<6> var;
    var << s_.gnss_hor_sigma_m * s_.gnss_hor_sigma_m, s_.gnss_hor_sigma_m * s_.gnss_hor_sigma_m,
        s_.gnss_ver_sigma_m * s_.gnss_ver_sigma_m, Vec3::Constant(s_.gnss_vel_sigma_mps * s_.gnss_vel_sigma_mps);
    filters::Vec<kN> dx = filters::Vec<kN>::Zero();
    const auto info = filters::joseph_update<kN, 6>(dx, p_, r, h, filters::SqMat<6>(var.asDiagonal()));
    if (info.ok) inject(dx);
}

// The turbulence and the air-data offsets, correlated from one update to the next, are states; what is left (the
// sensors' noise through nav_air's smoothing, the gusts' departure from the model) has a sigma of its own before and
// after the loss (docs/navigation.md, "Keeping the GNSS calibration").
void InFlightAligner::update_air(const AirSample& air) {
    const double sigma = handed_over_ ? s_.air_vel_sigma_denied_mps : s_.air_vel_sigma_mps;
    const Mat3 r_nb = q_nb_.toRotationMatrix();
    const double tas = air.tas_mps - b_air_.x(), aoa = air.aoa_rad - b_air_.y(), aos = air.aos_rad - b_air_.z();
    const Vec3 a_n = r_nb * math::vtas_body(tas, aoa, aos);
    filters::Mat<3, kN> h = filters::Mat<3, kN>::Zero();
    h.block<3, 3>(0, kPhi) = math::skew(a_n);
    h.block<3, 3>(0, kV) = Mat3::Identity();
    h.block<3, 3>(0, kW) = -Mat3::Identity();
    h.block<3, 3>(0, kT) = -Mat3::Identity();
    h.block<3, 3>(0, kAd) = r_nb * denied::vtas_jacobian(tas, aoa, aos);
    const filters::Vec<3> r = a_n + wind_n_ + turb_n_ - v_n_;
    filters::Vec<kN> dx = filters::Vec<kN>::Zero();
    const auto info = filters::joseph_update<kN, 3>(
        dx, p_, r, h, filters::SqMat<3>::Identity() * (sigma * sigma));
    if (info.ok) inject(dx);
}

void InFlightAligner::inject(const filters::Vec<kN>& dx) {
    q_nb_ = (math::quat_from_rotv(dx.segment<3>(kPhi)) * q_nb_).normalized();
    v_n_ += dx.segment<3>(kV);
    const earth::Radii rr = earth::radii(lat_rad_);
    lat_rad_ += dx(kP) / (rr.m_m + h_m_);
    lon_rad_ = math::wrap_pi(lon_rad_ + dx(kP + 1) / ((rr.n_m + h_m_) * std::cos(lat_rad_)));
    h_m_ -= dx(kP + 2);
    e_gyr_ += dx.segment<3>(kBg);
    e_acc_ += dx.segment<3>(kBa);
    e_mag_ += dx.segment<3>(kEm);
    b_dev_ += dx.segment<3>(kBd);
    wind_n_ += dx.segment<3>(kW);
    turb_n_ += dx.segment<3>(kT);
    b_air_ += dx.segment<3>(kAd);
    for (int i = 0; i < 3; ++i) m_mag_.row(i) += dx.segment<3>(kM + 3 * i).transpose();
}

double InFlightAligner::tilt_sigma_rad() const { return std::sqrt(std::max(p_(kPhi, kPhi), p_(kPhi + 1, kPhi + 1))); }
double InFlightAligner::heading_sigma_rad() const { return std::sqrt(p_(kPhi + 2, kPhi + 2)); }
Vec3 InFlightAligner::air_offsets_sigma() const { return p_.diagonal().segment<3>(kAd).cwiseMax(0.0).cwiseSqrt(); }

AttitudeEstimate InFlightAligner::estimate(std::uint64_t k, double t_s) const {
    AttitudeEstimate e{state(), {k, t_s}};
    const math::Euler eu = math::euler_from_quat(q_nb_);
    e.euler_rad = {eu.yaw_rad, eu.pitch_rad, eu.bank_rad};
    e.att_sigma_rad = p_.diagonal().segment<3>(kPhi).cwiseMax(0.0).cwiseSqrt();
    return e;
}

AttitudeHandover InFlightAligner::handover() const {
    AttitudeHandover h{state()};
    constexpr int kIdx[4] = {kPhi, kBg, kEm, kBd};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) h.p_err.block<3, 3>(3 * i, 3 * j) = p_.block<3, 3>(kIdx[i], kIdx[j]);
    return h;
}

Alignment InFlightAligner::alignment() const {
    Alignment a;
    a.q_nb = q_nb_;
    a.att_sigma_rad = std::max(tilt_sigma_rad(), heading_sigma_rad());
    const auto sig = [this](int i) { return Vec3(p_.diagonal().segment<3>(i).cwiseSqrt()); };
    a.gyr_err_rps = e_gyr_;
    a.gyr_err_sigma_rps = sig(kBg);
    a.acc_err_mps2 = e_acc_;
    a.acc_err_sigma_mps2 = sig(kBa);
    a.mag_err_nT = e_mag_;
    a.mag_err_sigma_nT = sig(kEm);
    a.b_dev_n_nT = b_dev_;
    a.b_dev_sigma_nT = sig(kBd);
    return a;
}

bool step_in_flight_aligner(InFlightAligner& a, double t_s, const ImuSample& imu, const MagSample& mag,
                            const GnssSample& gnss, const AirSample& air, const Alignment* published) {
    if (!checks::imu_ok(imu) || !checks::mag_ok(mag)) return false;
    const bool fix = gnss.fix_valid && checks::gnss_fix_ok(gnss);
    if (!a.started()) {
        if (!fix) return false;
        if (published != nullptr) {
            if (published->valid()) a.start(t_s, *published, imu, gnss, checks::air_ok(air) ? &air : nullptr);
        } else if (checks::air_ok(air)) {
            a.start(t_s, imu, mag, gnss, air);
        }
        return false;
    }
    return a.step(t_s, imu, mag, fix ? &gnss : nullptr, checks::air_ok(air) ? &air : nullptr);
}

}  // namespace gdnav::nav
