#include "earth/gravity.hpp"

#include <cmath>

namespace gdnav::core::earth {

double normal_gravity_msl_mps2(double lat_rad) {
    const double s2 = std::sin(lat_rad) * std::sin(lat_rad);
    return wgs84::kGammaE_mps2 * (1.0 + wgs84::kK * s2) / std::sqrt(1.0 - wgs84::kE2 * s2);
}

double normal_gravity_mps2(double lat_rad, double h_m) {
    return normal_gravity_sin2_mps2(std::sin(lat_rad) * std::sin(lat_rad), h_m);
}

double normal_gravity_sin2_mps2(double s2, double h_m) {
    using namespace wgs84;
    const double g_msl = kGammaE_mps2 * (1.0 + kK * s2) / std::sqrt(1.0 - kE2 * s2);
    return g_msl * (1.0 - 2.0 / kA_m * (1.0 + kF + kM - 2.0 * kF * s2) * h_m + 3.0 / (kA_m * kA_m) * h_m * h_m);
}

EarthTruthParams draw_earth_truth(rnd::Stream& stream, const EarthTruthSigmas& s) {
    EarthTruthParams p;
    p.dg_mps2 = s.dg_mps2 * stream.normal();
    p.tilt_rad = s.tilt_rad * stream.normal();
    p.tilt_axis_bearing_rad = math::deg2rad(static_cast<double>(stream.uniform_int(-179, 180)));
    p.mag_dev_n_nT.x() = s.mag_n_nT.x() * stream.normal();
    p.mag_dev_n_nT.y() = s.mag_n_nT.y() * stream.normal();
    p.mag_dev_n_nT.z() = s.mag_n_nT.z() * stream.normal();
    return p;
}

TrueGravity::TrueGravity(const EarthTruthParams& p) : dg_mps2_(p.dg_mps2) {
    const Vec3 axis(std::cos(p.tilt_axis_bearing_rad), std::sin(p.tilt_axis_bearing_rad), 0.0);
    tilt_ = math::quat_from_rotv(axis * p.tilt_rad).toRotationMatrix();
}

Vec3 TrueGravity::apply(const Vec3& g_model_n) const {
    const double g = g_model_n.norm();
    return tilt_ * (g_model_n * ((g + dg_mps2_) / g));
}

}  // namespace gdnav::core::earth
