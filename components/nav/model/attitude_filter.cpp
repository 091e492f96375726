#include "attitude_filter.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "filters/quat_jacobians.hpp"
#include "math/rotation.hpp"
#include "nav_earth.hpp"
#include "tuning_ranges.hpp"

namespace gdnav::nav {

using config::Range;
using namespace tuning_ranges;

using filters::Quat4;

namespace {
// The update with one sensor's rows of the measurement only: the IMU's (the first 6) or the magnetometer's (the
// last 3), when the other sensor's sample was rejected. Returns the update's NIS.
template <int N>
double one_sensor_update(filters::Vec<N>& x, filters::SqMat<N>& p, const att::MeasVec& r,
                         const filters::Mat<att::kM, N>& h, const att::MeasVec& r_diag, bool imu) {
    if (imu)
        return filters::joseph_update_diag<N, 6>(x, p, r.head<6>().eval(), h.template topRows<6>().eval(),
                                                 r_diag.head<6>().eval())
            .nis;
    return filters::joseph_update_diag<N, 3>(x, p, r.tail<3>().eval(), h.template bottomRows<3>().eval(),
                                             r_diag.tail<3>().eval())
        .nis;
}
}  // namespace

att::SpecificForceModel parse_specific_force_model(const config::Config& variant) {
    const std::string m =
        variant.get_choice("specific_force", {"baseline", "zero_fb_derivatives", "zero_fn_derivatives"});
    if (m == "zero_fb_derivatives") return att::SpecificForceModel::kZeroBodyDerivatives;
    if (m == "zero_fn_derivatives") return att::SpecificForceModel::kZeroNedDerivatives;
    return att::SpecificForceModel::kBaseline;
}

AttitudeFormulation parse_attitude_formulation(const config::Config& variant) {
    return variant.get_choice("filter", "additive", {"additive", "error_state"}) == "error_state"
               ? AttitudeFormulation::kErrorState
               : AttitudeFormulation::kAdditive;
}

void AttitudeFilter::configure(const config::Config& tuning, const config::Config& variant, rnd::Stream stream) {
    Tuning t;
    t.dt_s = tuning.get_double("dt_s", Range{1e-4, 1.0});
    t.transition_order = static_cast<int>(tuning.get_int("transition_order", 1, 4));
    const config::Config q = tuning.child("q_per_step");
    t.q_diag.segment<4>(att::kQ).setConstant(q.get_double("q", kVariance));
    t.q_diag.segment<3>(att::kW).setConstant(q.get_double("w_nb_rad2ps2", kVariance));
    t.q_diag.segment<3>(att::kEgyr).setConstant(q.get_double("gyr_bias_rad2ps2", kVariance));
    t.q_diag.segment<3>(att::kEmag).setConstant(q.get_double("mag_bias_nT2", kVariance));
    t.q_diag.segment<3>(att::kBdev).setConstant(q.get_double("b_dev_nT2", kVariance));
    const config::Config r = tuning.child("r");
    t.r_diag.segment<3>(att::kYgyr).setConstant(r.get_double("gyr_rad2ps2", kPositiveVariance));
    t.r_diag.segment<3>(att::kYacc) = r.get_vec3("acc_m2ps4", kPositiveVariance);
    t.r_diag.segment<3>(att::kYmag).setConstant(r.get_double("mag_nT2", kPositiveVariance));
    t.gyr_noise_var = tuning.get_double("gyr_noise_var_rad2ps2", kVariance);
    const config::Config init = tuning.child("init");
    t.init_mode = init.get_choice("mode", {"measurements", "alignment"}) == "alignment" ? InitMode::kAlignment
                                                                                         : InitMode::kMeasurements;
    const config::Config im = init.child("measurements");
    t.init_sigmas.tilt_rad = im.get_angle_deg("tilt_sigma_deg", Range{0.0, 30.0});
    t.init_sigmas.heading_rad = im.get_angle_deg("heading_sigma_deg", Range{0.0, 180.0});
    t.init_sigmas.gyr_bias_rps.setConstant(im.get_angle_deg("gyr_bias_sigma_dps", Range{0.0, 1.0e3}));
    t.init_sigmas.mag_bias_nT = im.get_vec3("mag_bias_sigma_nT", Range{0.0, kMaxSigma});
    t.init_sigmas.b_dev_nT = im.get_vec3("b_dev_sigma_nT", Range{0.0, kMaxSigma});
    t.align_q_p0 = init.child("alignment").get_double("q_p0", Range{0.0, 1.0});
    t.model = parse_specific_force_model(variant);
    t.formulation = parse_attitude_formulation(variant);
    tuning.finish();
    variant.finish();
    configure(t, stream);
}

void AttitudeFilter::configure(const Tuning& tuning, rnd::Stream stream) {
    tun_ = tuning;
    qe_diag_ = eskf::process_noise(tun_.q_diag);
    stream_ = stream;
    rej_ = {};
    pos_held_valid_ = false;
    initialized_ = false;
}

AttitudeEstimate AttitudeFilter::initialize(std::uint64_t k, double t_s, const ImuSample& imu, const MagSample& mag,
                                            const AirDataEstimate& air, const GnssSample& gnss,
                                            const Alignment* align) {
    if (!checks::imu_ok(imu) || !checks::mag_ok(mag))
        throw std::invalid_argument("AttitudeFilter::initialize: non-finite or out-of-range IMU or magnetometer sample");
    AttitudeInit in;
    if (tun_.init_mode == InitMode::kAlignment) {
        if (align == nullptr || !align->valid())
            throw std::invalid_argument("attitude init.mode alignment needs the alignment published by the sensors");
        in = init_from_alignment(imu, *align);
    } else {
        if (!gnss.fix_valid) throw std::invalid_argument("attitude init.mode measurements needs a valid GNSS fix");
        const MeasurementInitSigmas& s = tun_.init_sigmas;
        const Vec3 vtas_b = math::vtas_body(air.tas_mps, air.aoa_rad, air.aos_rad);
        const Vec3 f_corr = imu.f_b_mps2 - imu.w_b_rps.cross(vtas_b);
        in.q_nb = coarse_attitude(f_corr, mag.b_b_nT, earth::magnetic_model_n(gnss.lon_rad, gnss.lat_rad));
        in.w_nb_b_rps = imu.w_b_rps - in.q_nb.conjugate() * earth::w_ie_n(gnss.lat_rad);
        in.att_sigma_rad = s.tilt_rad;
        in.heading_sigma_rad = s.heading_rad;
        in.gyr_bias_sigma_rps = s.gyr_bias_rps;
        in.mag_bias_sigma_nT = s.mag_bias_nT;
        in.b_dev_sigma_nT = s.b_dev_nT;
    }
    in.w_nb_sigma_rps = (in.gyr_bias_sigma_rps.array().square() + tun_.gyr_noise_var).sqrt();
    return initialize(k, t_s, in);
}

AttitudeInit AttitudeFilter::init_from_alignment(const ImuSample& imu, const Alignment& align) const {
    AttitudeInit in;
    in.q_nb = align.q_nb.normalized();
    in.gyr_bias_rps = align.gyr_err_rps;
    in.mag_bias_nT = align.mag_err_nT;
    in.b_dev_n_nT = align.b_dev_n_nT;
    if (tun_.align_q_p0 > 0.0) {
        in.q_p0 = tun_.align_q_p0;  // the reference's fixed (overconfident) P0
    } else {
        in.att_sigma_rad = align.att_sigma_rad;
    }
    in.gyr_bias_sigma_rps = align.gyr_err_sigma_rps;
    in.mag_bias_sigma_nT = align.mag_err_sigma_nT;
    in.b_dev_sigma_nT = align.b_dev_sigma_nT;
    in.w_nb_b_rps = imu.w_b_rps - in.gyr_bias_rps;  // Earth and transport rates ignored, as the reference
    return in;
}

AttitudeEstimate AttitudeFilter::realign(std::uint64_t k, double t_s, const ImuSample& imu, const Alignment& align) {
    if (!align.valid()) throw std::invalid_argument("AttitudeFilter::realign: no alignment");
    if (!checks::imu_ok(imu)) throw std::invalid_argument("AttitudeFilter::realign: non-finite or out-of-range IMU sample");
    AttitudeInit in = init_from_alignment(imu, align);
    in.w_nb_sigma_rps = (in.gyr_bias_sigma_rps.array().square() + tun_.gyr_noise_var).sqrt();
    return initialize(k, t_s, in);
}

Quat AttitudeFilter::set_state(const AttitudeState& s) {
    const Quat qn = s.q_nb.normalized();
    x_.setZero();
    x_.segment<4>(att::kQ) = math::to_wxyz(qn);
    x_.segment<3>(att::kW) = s.w_nb_b_rps;
    x_.segment<3>(att::kEgyr) = s.gyr_bias_rps;
    x_.segment<3>(att::kEmag) = s.mag_bias_nT;
    x_.segment<3>(att::kBdev) = s.b_dev_n_nT;
    return qn;
}

AttitudeEstimate AttitudeFilter::hand_over(std::uint64_t k, double t_s, const AttitudeHandover& h) {
    const Quat qn = set_state(h);
    // Error order of h.p_err: phi_n (0..2), E_gyr (3..5), E_mag (6..8), B_dev (9..11).
    filters::Mat<att::kN, 12> t = filters::Mat<att::kN, 12>::Zero();
    t.block<4, 3>(att::kQ, 0) = 0.5 * filters::xi(x_.segment<4>(att::kQ)) * qn.toRotationMatrix().transpose();
    t.block<3, 3>(att::kW, 3) = -Eigen::Matrix3d::Identity();
    t.block<3, 3>(att::kEgyr, 3).setIdentity();
    t.block<3, 3>(att::kEmag, 6).setIdentity();
    t.block<3, 3>(att::kBdev, 9).setIdentity();
    p_ = t * h.p_err * t.transpose();
    p_.diagonal().segment<3>(att::kW).array() += tun_.gyr_noise_var;
    filters::symmetrize<att::kN>(p_);
    pe_ = eskf::from_additive(x_, p_);
    initialized_ = true;
    return output(k, t_s);
}

AttitudeEstimate AttitudeFilter::initialize(std::uint64_t k, double t_s, const AttitudeInit& in) {
    const Quat qn = set_state(in);
    p_.setZero();
    if (in.att_sigma_rad > 0.0 && in.heading_sigma_rad > 0.0) {
        // NED-side sigmas, carried to the body-side angle error of Xi: dtheta_b = R^T dtheta_n.
        const filters::Mat43 xi = filters::xi(x_.segment<4>(att::kQ));
        const Eigen::Matrix3d r = qn.toRotationMatrix();
        const Eigen::Vector3d var(in.att_sigma_rad * in.att_sigma_rad, in.att_sigma_rad * in.att_sigma_rad,
                                  in.heading_sigma_rad * in.heading_sigma_rad);
        p_.block<4, 4>(att::kQ, att::kQ) = 0.25 * xi * r.transpose() * var.asDiagonal() * r * xi.transpose();
    } else if (in.att_sigma_rad > 0.0) {
        const filters::Mat43 xi = filters::xi(x_.segment<4>(att::kQ));
        p_.block<4, 4>(att::kQ, att::kQ) = 0.25 * in.att_sigma_rad * in.att_sigma_rad * xi * xi.transpose();
    } else {
        p_.block<4, 4>(att::kQ, att::kQ) = in.q_p0 * Eigen::Matrix4d::Identity();
    }
    p_.diagonal().segment<3>(att::kW) = in.w_nb_sigma_rps.array().square();
    p_.diagonal().segment<3>(att::kEgyr) = in.gyr_bias_sigma_rps.array().square();
    p_.diagonal().segment<3>(att::kEmag) = in.mag_bias_sigma_nT.array().square();
    p_.diagonal().segment<3>(att::kBdev) = in.b_dev_sigma_nT.array().square();
    pe_ = eskf::from_additive(x_, p_);
    initialized_ = true;
    return output(k, t_s);
}

void AttitudeFilter::normalise_quaternion() { x_.segment<4>(att::kQ).normalize(); }

AttitudeEstimate AttitudeFilter::step(std::uint64_t k, double t_s, const ImuSample& imu, const MagSample& mag,
                                      const PositionEstimate& pos_prev) {
    if (!initialized_) throw std::logic_error("AttitudeFilter::step before initialize");
    const bool error_state = tun_.formulation == AttitudeFormulation::kErrorState;
    // Propagate.
    // A is zero outside its leading 7x7 block (q rows, q and w_nb columns): Phi = diag(Phi_7, I).
    // Both covariances use Phi at x+(k-1) (the covariance does not depend on the state update that follows).
    if (error_state) {
        filters::propagate_covariance_leading_diag<eskf::kN, eskf::kJ>(
            pe_, eskf::transition_leading(x_, tun_.dt_s), qe_diag_);
    } else {
        const filters::SqMat<att::kJ> phi = filters::transition_matrix<att::kJ>(
            att::state_jacobian(x_).topLeftCorner<att::kJ, att::kJ>(), tun_.dt_s, tun_.transition_order);
        filters::propagate_covariance_leading_diag<att::kN, att::kJ>(p_, phi, tun_.q_diag);
    }
    x_ += tun_.dt_s * att::derivative(x_);
    normalise_quaternion();
    // Input checks: a rejected previous position estimate is replaced by the last good one.
    bool pos_good = checks::position_estimate_ok(pos_prev);
    if (pos_good) {
        pos_held_ = pos_prev;
        pos_held_valid_ = true;
    } else {
        ++rej_.position;
        pos_good = pos_held_valid_;
    }
    const bool mag_good = checks::mag_ok(mag);
    bool imu_good = checks::imu_ok(imu);
    if (!imu_good) ++rej_.imu;
    if (!mag_good) ++rej_.mag;
    imu_good = imu_good && pos_good;  // the accelerometer rows need p_n
    // Update with the p_n vector of the previous position estimate (rows 0-5: IMU, rows 6-8: magnetometer).
    const att::PnVector pn = att::make_pn(pos_held_valid_ ? pos_held_ : pos_prev);
    att::MeasVec y;
    y << imu.w_b_rps, imu.f_b_mps2, mag.b_b_nT;
    if (error_state) {
        step_error_state(imu_good, mag_good, y, pn);
        return output(k, t_s);
    }
    if (imu_good && mag_good) {
        const att::MeasVec r = y - att::observe(x_, pn, tun_.model);
        const auto info = filters::joseph_update_diag<att::kN, att::kM>(
            x_, p_, r, att::observation_jacobian(x_, pn, tun_.model), tun_.r_diag);
        last_nis_ = info.nis;
    } else if (imu_good || mag_good) {
        const att::MeasVec r = y - att::observe(x_, pn, tun_.model);
        const att::MeasJac h = att::observation_jacobian(x_, pn, tun_.model);
        last_nis_ = one_sensor_update<att::kN>(x_, p_, r, h, tun_.r_diag, imu_good);
    } else {
        last_nis_ = 0.0;
    }
    normalise_quaternion();
    return output(k, t_s);
}

void AttitudeFilter::step_error_state(bool imu_good, bool mag_good, const att::MeasVec& y, const att::PnVector& pn) {
    last_nis_ = 0.0;
    if (!imu_good && !mag_good) return;
    const att::MeasVec r = y - att::observe(x_, pn, tun_.model);
    const eskf::ErrJac h = eskf::observation_jacobian(x_, pn, tun_.model);
    eskf::ErrVec dx = eskf::ErrVec::Zero();
    if (imu_good && mag_good) {
        last_nis_ = filters::joseph_update_diag<eskf::kN, att::kM>(dx, pe_, r, h, tun_.r_diag).nis;
    } else {
        last_nis_ = one_sensor_update<eskf::kN>(dx, pe_, r, h, tun_.r_diag, imu_good);
    }
    eskf::inject(x_, pe_, dx);
}

double AttitudeFilter::fuse_yaw(double yaw_rad, double yaw_var_rad2) {
    const double r = math::wrap_pi(yaw_rad - math::euler_from_quat(estimate_q()).yaw_rad);
    const filters::Vec<1> innov = filters::Vec<1>::Constant(r);
    const filters::Vec<1> var = filters::Vec<1>::Constant(yaw_var_rad2);
    if (tun_.formulation == AttitudeFormulation::kErrorState) {
        filters::Mat<1, eskf::kN> h = filters::Mat<1, eskf::kN>::Zero();
        h(0, 2) = 1.0;
        eskf::ErrVec dx = eskf::ErrVec::Zero();
        const double nis = filters::joseph_update_diag<eskf::kN, 1>(dx, pe_, innov, h, var).nis;
        eskf::inject(x_, pe_, dx);
        return nis;
    }
    filters::Mat<1, att::kN> h = filters::Mat<1, att::kN>::Zero();
    h.block<1, 4>(0, att::kQ) = filters::att_error_jacobian(x_.segment<4>(att::kQ)).row(2);
    const double nis = filters::joseph_update_diag<att::kN, 1>(x_, p_, innov, h, var).nis;
    normalise_quaternion();
    return nis;
}

Eigen::Matrix3d AttitudeFilter::attitude_covariance_n() const {
    if (tun_.formulation == AttitudeFormulation::kErrorState) return pe_.topLeftCorner<3, 3>();
    const filters::Mat34 g = filters::att_error_jacobian(x_.segment<4>(att::kQ));
    return g * p_.block<4, 4>(att::kQ, att::kQ) * g.transpose();
}

AttitudeEstimate AttitudeFilter::output(std::uint64_t k, double t_s) const {
    AttitudeEstimate e;
    e.stamp = {k, t_s};
    e.q_nb = math::from_wxyz(x_.segment<4>(att::kQ));
    const math::Euler eu = math::euler_from_quat(e.q_nb);
    e.euler_rad = {eu.yaw_rad, eu.pitch_rad, eu.bank_rad};
    e.w_nb_b_rps = x_.segment<3>(att::kW);
    e.gyr_bias_rps = x_.segment<3>(att::kEgyr);
    e.mag_bias_nT = x_.segment<3>(att::kEmag);
    e.b_dev_n_nT = x_.segment<3>(att::kBdev);
    e.att_sigma_rad = attitude_covariance_n().diagonal().cwiseMax(0.0).cwiseSqrt();
    return e;
}

}  // namespace gdnav::nav
