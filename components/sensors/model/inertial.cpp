#include "sensors/model/inertial.hpp"

namespace gdnav::sensors {

void InertialSensors::configure(const InertialParams& params, rnd::Stream stream) {
    params_ = params;
    rnd::Stream platform = stream.child("platform");
    mount_ = draw_platform(params.platform, platform);
    gyr_.configure(params.gyr, params.bias_drift_band, params.dt_s, InertialTriad::Coupling::kFull,
                   stream.child("gyr"));
    acc_.configure(params.acc, params.bias_drift_band, params.dt_s, InertialTriad::Coupling::kLowerTriangular,
                   stream.child("acc"));
    const math::Mat3 r_pb_true = mount_.r_bp_true.transpose();
    a_gyr_ = mount_.r_bp_est * (math::Mat3::Identity() + gyr_.scale_cross()) * r_pb_true;
    a_acc_ = mount_.r_bp_est * (math::Mat3::Identity() + acc_.scale_cross()) * r_pb_true;
    has_prev_ = false;
    w_prev_.setZero();
}

ImuMeasurement InertialSensors::measure(std::uint64_t k, double t_s, const InertialTruth& truth) {
    ImuMeasurement out;
    out.step = k;
    out.t_s = t_s;

    const math::Vec3& w = truth.w_ib_b_rps;
    const math::Vec3 gyr_noise = gyr_.noise_sample();
    out.e_gyr_rps = a_gyr_ * w - w + gyr_.sample_bias();
    out.w_b_rps = w + out.e_gyr_rps + gyr_noise;

    // Lever arms: true one from the truth rates, compensated one from the measured rate.
    const math::Vec3 t_rb = cg_position_m(params_.platform, truth.mass_kg);
    const math::Vec3 t_bp_true = mount_.t_rp_true_m - t_rb;
    const math::Vec3 t_bp_est = mount_.t_rp_est_m - t_rb;
    const math::Vec3 l_true = w.cross(w.cross(t_bp_true)) + truth.dw_ib_b_rps2.cross(t_bp_true);
    const math::Vec3& wm = out.w_b_rps;
    const bool consecutive = has_prev_ && k == k_prev_ + 1;
    const math::Vec3 dwm = consecutive ? math::Vec3((wm - w_prev_) / params_.dt_s) : math::Vec3::Zero();
    const math::Vec3 l_est = wm.cross(wm.cross(t_bp_est)) + dwm.cross(t_bp_est);
    w_prev_ = wm;
    k_prev_ = k;
    has_prev_ = true;

    const math::Vec3& f = truth.f_ib_b_mps2;
    const math::Vec3 acc_noise = acc_.noise_sample();
    out.e_acc_mps2 = a_acc_ * (f + l_true) - l_est - f + acc_.sample_bias();
    out.f_b_mps2 = f + out.e_acc_mps2 + acc_noise;
    return out;
}

InertialNoise InertialSensors::noise() const {
    InertialNoise n;
    n.gyr_noise_rps = gyr_.noise_sigma();
    n.gyr_drift_step_rps = gyr_.drift_step_sigma();
    n.gyr_drift_band_rps = gyr_.drift_band();
    n.gyr_bias_offset_rps = params_.gyr.bias_offset;
    n.acc_noise_mps2 = acc_.noise_sigma();
    n.acc_drift_step_mps2 = acc_.drift_step_sigma();
    n.acc_drift_band_mps2 = acc_.drift_band();
    n.acc_bias_offset_mps2 = params_.acc.bias_offset;
    return n;
}

}  // namespace gdnav::sensors
