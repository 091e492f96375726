#pragma once
// Normal ("model") gravity and the per-run "true" gravity.
//
// Model gravity (gravitation + centrifugal, normal to the ellipsoid), Somigliana with a second-order altitude term:
//   g_MSL(lat) = gamma_e (1 + k sin^2 lat) / sqrt(1 - e^2 sin^2 lat)
//   g(lat, h)  = g_MSL [1 - (2/a)(1 + f + m - 2 f sin^2 lat) h + (3/a^2) h^2]
//   g_model^n  = (0, 0, g(lat, h))
// True gravity: constant per-run deviations (EarthTruthParams) applied to the model vector,
//   g_true^n = R(axis = (cos b, sin b, 0), angle = tilt) * g_model^n * (1 + dg / |g_model^n|),
// i.e. the modulus becomes |g| + dg and the direction is tilted by `tilt` about a horizontal axis of bearing b.
// The per-run deviations (and the magnetic deviation of magnetic.hpp) are drawn together by draw_earth_truth().
#include "earth/wgs84.hpp"
#include "random/stream.hpp"

namespace gdnav::core::earth {

double normal_gravity_msl_mps2(double lat_rad);
double normal_gravity_mps2(double lat_rad, double h_m);
double normal_gravity_sin2_mps2(double sin2_lat, double h_m);  // from sin^2(lat)
inline Vec3 gravity_model_n(double lat_rad, double h_m) { return {0.0, 0.0, normal_gravity_mps2(lat_rad, h_m)}; }

// Constant per-run deviations of the true Earth fields from their models.
struct EarthTruthParams {
    double dg_mps2{0.0};                // gravity modulus offset
    double tilt_rad{0.0};               // gravity direction tilt (deflection of the vertical)
    double tilt_axis_bearing_rad{0.0};  // bearing of the horizontal tilt axis
    Vec3 mag_dev_n_nT{Vec3::Zero()};    // constant NED magnetic field deviation (true - model)
};

// Standard deviations of the draws (reference section 1.3 and 1.5; WMM2015 error budget for the field).
struct EarthTruthSigmas {
    double dg_mps2{1e-4};
    double tilt_rad{math::deg2rad(0.0028)};
    Vec3 mag_n_nT{138.0, 89.0, 165.0};
};

// Draw order: dg ~ N(0, s_dg^2); tilt ~ N(0, s_tilt^2); bearing ~ U{-179..180} integer degrees;
// mag N, E, D ~ N(0, s^2). Pass zero sigmas for a model-equals-truth run.
EarthTruthParams draw_earth_truth(rnd::Stream& stream, const EarthTruthSigmas& sigmas = {});

// True gravity for one run: precomputes the tilt rotation.
class TrueGravity {
public:
    TrueGravity() = default;
    explicit TrueGravity(const EarthTruthParams& p);
    [[nodiscard]] Vec3 apply(const Vec3& g_model_n) const;
    [[nodiscard]] Vec3 at(double lat_rad, double h_m) const { return apply(gravity_model_n(lat_rad, h_m)); }

private:
    Mat3 tilt_{Mat3::Identity()};
    double dg_mps2_{0.0};
};

}  // namespace gdnav::core::earth
namespace gdnav { namespace earth = core::earth; }  // the short name (docs/architecture.md, "Namespaces")
