#pragma once
// WGS84 ellipsoid geometry and Earth kinematics used by the flight physics and the navigation filters.
//
//   Constants      a = 6378137 m, f = 1/298.257223563, GM = 3.986004418e14 m^3/s^2, w_ie = 7.292115e-5 rad/s,
//                  e^2 = f (2 - f), g'^2 = (a^2 - b^2) / b^2 (second eccentricity squared), b = a (1 - f).
//   Radii          N(lat) = a / sqrt(1 - e^2 sin^2 lat)   (prime vertical)
//                  M(lat) = N / (1 + g'^2 cos^2 lat)      (meridian; equals a (1 - e^2) / (1 - e^2 sin^2 lat)^1.5)
//   Position rate  lon_dot = v_E / ((N + h) cos lat), lat_dot = v_N / (M + h), h_dot = -v_D
//   Earth rate     w_ie^n = w_ie (cos lat, 0, -sin lat)
//   Transport rate w_en^n = (v_E / (N + h), -v_N / (M + h), -v_E tan lat / (N + h))
//   Coriolis       a_cor^n = 2 w_ie^n x v^n   (the centrifugal term lives inside the normal gravity)
//   Geopotential   spherical Earth of radius R_E = 6356766 m: h = R_E H / (R_E - H), H = R_E h / (R_E + h)
//                  (the reference "geo_mix" choice: latitude independent).
// Geodetic <-> ECEF conversions use GeographicLib::Geocentric (exact, not the reference's fixed-point loop).
// Frames: n = local NED, e = ECEF. Angles in rad, lengths in m, velocities in m/s.
#include "math/rotation.hpp"

namespace gdnav::core::earth {

using math::Mat3;
using math::Vec3;

namespace wgs84 {
constexpr double kA_m = 6378137.0;                                    // semi-major axis
constexpr double kF = 1.0 / 298.257223563;                            // flattening
constexpr double kGM_m3ps2 = 3.986004418e14;                          // gravitational constant times Earth mass
constexpr double kOmegaIE_rps = 7.292115e-5;                          // Earth rotation rate
constexpr double kGammaE_mps2 = 9.7803253359;                         // normal gravity at the equator
constexpr double kGammaP_mps2 = 9.8321849378;                         // normal gravity at the poles
constexpr double kB_m = kA_m * (1.0 - kF);                            // semi-minor axis
constexpr double kE2 = kF * (2.0 - kF);                               // first eccentricity squared
constexpr double kEp2 = (kA_m * kA_m - kB_m * kB_m) / (kB_m * kB_m);  // second eccentricity squared
constexpr double kM = kOmegaIE_rps * kOmegaIE_rps * kA_m * kA_m * kB_m / kGM_m3ps2;
constexpr double kK = kB_m * kGammaP_mps2 / (kA_m * kGammaE_mps2) - 1.0;  // Somigliana constant
}  // namespace wgs84

constexpr double kG0_mps2 = 9.80665;           // standard gravity (defines geopotential metres)
constexpr double kRadiusGeopot_m = 6356766.0;  // sphere radius of the H <-> h conversion

struct Geodetic {
    double lon_rad{0.0};
    double lat_rad{0.0};
    double h_m{0.0};  // above the ellipsoid
};

struct Radii {
    double n_m{0.0};  // prime vertical radius of curvature N
    double m_m{0.0};  // meridian radius of curvature M
};

Radii radii(double lat_rad);

// ECEF position of a geodetic point and back (GeographicLib::Geocentric::WGS84()).
Vec3 ecef_from_geodetic(const Geodetic& p);
Geodetic geodetic_from_ecef(const Vec3& r_e_m);
// Rotation matrix R_en (NED components -> ECEF components) at the given point.
Mat3 dcm_ecef_from_ned(double lon_rad, double lat_rad);

// (lon_dot, lat_dot, h_dot) [rad/s, rad/s, m/s] from the NED ground velocity.
Vec3 position_rate(double lat_rad, double h_m, const Vec3& v_n_mps);
Vec3 position_rate(const Radii& r, double lat_rad, double h_m, const Vec3& v_n_mps);

Vec3 earth_rate_n(double lat_rad);
Vec3 transport_rate_n(double lat_rad, double h_m, const Vec3& v_n_mps);
Vec3 transport_rate_n(const Radii& r, double lat_rad, double h_m, const Vec3& v_n_mps);
Vec3 coriolis_n(double lat_rad, const Vec3& v_n_mps);

// Same quantities from a precomputed sin(lat), cos(lat) (per-step code evaluates the trigonometry once).
Radii radii_sc(double sin_lat, double cos_lat);
Vec3 position_rate_sc(const Radii& r, double cos_lat, double h_m, const Vec3& v_n_mps);
Vec3 earth_rate_n_sc(double sin_lat, double cos_lat);
Vec3 transport_rate_n_sc(const Radii& r, double sin_lat, double cos_lat, double h_m, const Vec3& v_n_mps);

// Spherical geopotential <-> geometric altitude conversion (R_E = 6356766 m).
constexpr double geometric_from_geopotential(double H_m) { return kRadiusGeopot_m * H_m / (kRadiusGeopot_m - H_m); }
constexpr double geopotential_from_geometric(double h_m) { return kRadiusGeopot_m * h_m / (kRadiusGeopot_m + h_m); }

}  // namespace gdnav::core::earth
namespace gdnav { namespace earth = core::earth; }  // the short name (docs/architecture.md, "Namespaces")
