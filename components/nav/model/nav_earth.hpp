#pragma once
// The navigation filters' view of the shared Earth and atmosphere toolkits (common/core/earth, common/core/atmosphere):
// thin adapters with the names the filter code uses, plus the partial derivatives its Jacobians need that the
// shared toolkits do not provide (dN/dlat, dM/dlat, dg/dlat, dg/dh). No second geodesy or INSA implementation.
//   WGS84 radii N, M; normal gravity g(lat, h) (Somigliana + altitude terms) with derivatives; Earth rate,
//   transport rate, Coriolis; ISA/INSA p(Hp), Hp(p), dp/dHp, dT, H(Hp, dT, dp), dp(H, Hp, dT); spherical H <-> h.
//   Onboard magnetic model: the shared bilinear MagneticModel with the filter's own copy of the four WMM corner
//   values (docs/navigation.md "Onboard Earth/atmosphere") — an onboard model is by nature separate from the
//   simulated truth's.
#include <Eigen/Core>

#include "atmosphere/insa.hpp"
#include "earth/wgs84.hpp"

namespace gdnav::nav::earth {

using Vec3 = Eigen::Vector3d;

// Constants: the shared toolkits' (docs/physics.md "Constants").
inline constexpr double kA_m = ::gdnav::earth::wgs84::kA_m;
inline constexpr double kF = ::gdnav::earth::wgs84::kF;
inline constexpr double kB_m = ::gdnav::earth::wgs84::kB_m;
inline constexpr double kE2 = ::gdnav::earth::wgs84::kE2;
inline constexpr double kGM_m3ps2 = ::gdnav::earth::wgs84::kGM_m3ps2;
inline constexpr double kWie_rps = ::gdnav::earth::wgs84::kOmegaIE_rps;
inline constexpr double kGe_mps2 = ::gdnav::earth::wgs84::kGammaE_mps2;
inline constexpr double kGp_mps2 = ::gdnav::earth::wgs84::kGammaP_mps2;
inline constexpr double kRE_m = ::gdnav::earth::kRadiusGeopot_m;
inline constexpr double kG0_mps2 = ::gdnav::atm::kG0_mps2;
inline constexpr double kR_JpkgK = ::gdnav::atm::kR_JpkgK;
inline constexpr double kBetaT_Kpm = ::gdnav::atm::kBetaT_Kpm;
inline constexpr double kT0_K = ::gdnav::atm::kT0_K;
inline constexpr double kP0_Pa = ::gdnav::atm::kP0_Pa;

struct Radii {
    double n_m{0.0};  // prime vertical radius of curvature N
    double m_m{0.0};  // meridian radius of curvature M
    double dn_dlat{0.0};
    double dm_dlat{0.0};
};
Radii radii(double lat_rad);

// Normal gravity magnitude g(lat, h) and its partial derivatives.
struct Gravity {
    double g_mps2{0.0};
    double dg_dlat{0.0};
    double dg_dh{0.0};
};
Gravity normal_gravity(double lat_rad, double h_m);
inline Vec3 gravity_n(double lat_rad, double h_m) { return {0.0, 0.0, normal_gravity(lat_rad, h_m).g_mps2}; }

Vec3 w_ie_n(double lat_rad);
Vec3 w_en_n(double lat_rad, double h_m, const Vec3& v_n_mps);
Vec3 a_cor_n(double lat_rad, const Vec3& v_n_mps);

// Geodetic kinematics: (lon_dot, lat_dot, h_dot) for a ground velocity in NED.
Vec3 geodetic_rates(double lat_rad, double h_m, const Vec3& v_n_mps);

// ISA / INSA.
double pressure_from_Hp(double hp_m);
double Hp_from_pressure(double p_pa);
double dpressure_dHp(double hp_m);
double dT_from(double t_k, double hp_m);
double H_from_Hp(double hp_m, double dt_k, double dp_pa);
double dp_from_H(double h_geopot_m, double hp_m, double dt_k);
double H_from_h(double h_m);
double h_from_H(double h_geopot_m);

// Onboard magnetic model B_model^N [nT].
Vec3 magnetic_model_n(double lon_rad, double lat_rad);

}  // namespace gdnav::nav::earth
