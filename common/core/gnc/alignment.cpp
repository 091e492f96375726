#include "gnc/alignment.hpp"

#include <cmath>

namespace gdnav::core::gnc {

using math::Quat;
using math::Vec3;

AlignmentErrors AlignmentErrors::from_config(const config::Config& cfg) {
    using config::Range;
    AlignmentErrors e;
    e.att_sigma_rad = math::deg2rad(cfg.get_double("att_error_sigma_deg", Range{0.0, 10.0}));
    e.normalise_error_axis = cfg.get_bool("normalise_error_axis");
    e.gyr_rel = cfg.get_double("gyr_rel_error", Range{0.0, 1.0});
    e.acc_rel = cfg.get_double("acc_rel_error", Range{0.0, 1.0});
    e.mag_rel = cfg.get_double("mag_rel_error", Range{0.0, 1.0});
    e.b_dev_rel = cfg.get_double("b_dev_rel_error", Range{0.0, 1.0});
    cfg.finish();
    return e;
}

Quat draw_attitude_error(double sigma_rad, bool normalise_axis, rnd::Stream& stream) {
    const double gamma = stream.normal(0.0, sigma_rad);
    const double p1 = math::deg2rad(static_cast<double>(stream.uniform_int(-179, 180)));
    const double p2 = math::deg2rad(0.5 * static_cast<double>(stream.uniform_int(-179, 180)));
    Vec3 a(std::cos(p1) * std::cos(p2), std::sin(p2), std::sin(p1));
    if (normalise_axis) a.normalize();
    return math::quat_from_rotv(gamma * a);
}

Vec3 perturb_relative(const Vec3& truth, double rel, rnd::Stream& stream) {
    const Vec3 nu = stream.normal3();
    return truth.cwiseProduct(Vec3::Ones() + rel * nu);
}

ImuAlignment align_imu(const AlignmentErrors& e, const Quat& q_nb_true, const Vec3& gyr_err_rps,
                       const Vec3& acc_err_mps2, rnd::Stream& stream) {
    ImuAlignment a;
    a.q_nb = (draw_attitude_error(e.att_sigma_rad, e.normalise_error_axis, stream) * q_nb_true).normalized();
    a.att_sigma_rad = e.att_sigma_rad;
    a.gyr_err_rps = perturb_relative(gyr_err_rps, e.gyr_rel, stream);
    a.gyr_err_sigma_rps = e.gyr_rel * gyr_err_rps.cwiseAbs();
    a.acc_err_mps2 = perturb_relative(acc_err_mps2, e.acc_rel, stream);
    a.acc_err_sigma_mps2 = e.acc_rel * acc_err_mps2.cwiseAbs();
    return a;
}

MagAlignment align_mag(const AlignmentErrors& e, const Vec3& mag_err_nT, const Vec3& b_dev_n_nT,
                       rnd::Stream& stream) {
    MagAlignment a;
    a.mag_err_nT = perturb_relative(mag_err_nT, e.mag_rel, stream);
    a.mag_err_sigma_nT = e.mag_rel * mag_err_nT.cwiseAbs();
    a.b_dev_n_nT = perturb_relative(b_dev_n_nT, e.b_dev_rel, stream);
    a.b_dev_sigma_nT = e.b_dev_rel * b_dev_n_nT.cwiseAbs();
    return a;
}

}  // namespace gdnav::core::gnc
