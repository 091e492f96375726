#pragma once
// ************************************************************************************************************
// TO BE REPLACED by common/earth and common/atmosphere once they land (the lead merges them). Minimal Earth and
// atmosphere math that the navigation filters need on board; numbers from models-nav.md §0, §2.4, §5.3, §9.
// ************************************************************************************************************
//   WGS84 radii:  N = a / sqrt(1 - e^2 sin^2 lat),  M = a (1 - e^2) / (1 - e^2 sin^2 lat)^1.5
//   Normal gravity (Somigliana + 2nd-order altitude terms), purely vertical in NED:
//     g0(lat) = g_e (1 + k sin^2 lat) / sqrt(1 - e^2 sin^2 lat),  k = b g_p / (a g_e) - 1
//     g(lat, h) = g0 [1 - (2/a)(1 + f + m - 2 f sin^2 lat) h + (3/a^2) h^2],  m = w_ie^2 a^2 b / GM
//   Earth rate  w_ie_n = w_ie (cos lat, 0, -sin lat);  transport rate w_en_n = (vE/(N+h), -vN/(M+h), -vE tan lat/(N+h))
//   Coriolis    a_cor_n = 2 w_ie_n x v_n
//   ISA/INSA:   p(Hp) = p0 (1 + beta Hp / T0)^(-g0/(R beta));  Hp(p) = (T0/beta)((p/p0)^(-beta R/g0) - 1)
//               dT = T - (T0 + beta Hp)
//               H(Hp, dT, dp) = Hp - Hp0 + (dT/beta) ln[(T0 + beta Hp)/(T0 + beta Hp0)],  Hp0 = Hp(p0 + dp)
//               (integral of dH/dHp = T/T_isa = 1 + dT/(T0 + beta Hp) from Hp0, where H = 0)
//               dp(H, Hp, dT): the inverse for dp (Newton on Hp0), used by the GNSS-aided phase.
//   Spherical geopotential <-> geometric altitude with R_E = 6 356 766 m:  H = R_E h/(R_E + h), h = R_E H/(R_E - H)
//   Onboard magnetic model: bilinear interpolation in (lon, lat) of four WMM corner values (models-nav.md §9,
//   "mix" area around lon 270..271 deg, lat 44..45 deg), linear extrapolation outside.
#include <Eigen/Core>

namespace gdnav::nav::earth {

using Vec3 = Eigen::Vector3d;

// WGS84 and physical constants (models-nav.md §0).
inline constexpr double kA_m = 6378137.0;
inline constexpr double kF = 1.0 / 298.257223563;
inline constexpr double kB_m = kA_m * (1.0 - kF);
inline constexpr double kE2 = kF * (2.0 - kF);
inline constexpr double kGM_m3ps2 = 3.986004418e14;
inline constexpr double kWie_rps = 7.292115e-5;
inline constexpr double kGe_mps2 = 9.7803253359;  // normal gravity at the equator
inline constexpr double kGp_mps2 = 9.8321849378;  // normal gravity at the poles
inline constexpr double kRE_m = 6356766.0;        // spherical Earth radius for H <-> h
// ISA
inline constexpr double kG0_mps2 = 9.80665;
inline constexpr double kR_JpkgK = 287.05287;
inline constexpr double kBetaT_Kpm = -6.5e-3;
inline constexpr double kT0_K = 288.15;
inline constexpr double kP0_Pa = 101325.0;

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
