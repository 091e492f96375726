#pragma once
#include <limits>

// ISA and the non-standard INSA troposphere (temperature offset dT and pressure offset dp at mean sea level).
// Hp = pressure altitude, H = geopotential altitude [m]; SI units (Pa, K, kg/m^3, m/s).
//
//   p(Hp)        = p0 (1 + bT Hp / T0)^(-g0 / (R bT))                  (pressure depends on Hp only)
//   Hp(p)        = (T0 / bT) [(p / p0)^(-bT R / g0) - 1]
//   T(Hp; dT)    = T0 + dT + bT Hp                                      (ISA temperature shifted by dT)
//   rho = p / (R T),  a = sqrt(kappa R T)
//   Hp_MSL(dp)   = Hp(p0 + dp)
//   H(Hp; dT,dp) = Hp - Hp_MSL + (dT / bT) ln[(T0 + bT Hp) / (T0 + bT Hp_MSL)]       (dH/dHp = T / T_ISA)
//   Hp(H; dT,dp) : inverse of the above by Newton iteration to convergence (stops once a step is below 1 mm,
//                  leaving an error below 1e-11 m: f''/f' < 1e-6 /m, quadratic convergence)
//   pitot        : p_t = p (1 + (kappa-1)/2 M^2)^(kappa/(kappa-1)),  M = V / a;
//                  V = sqrt(2 kappa/(kappa-1) (p/rho) [(p_t/p)^((kappa-1)/kappa) - 1])
// Constants: R = 287.05287 J/(kg K), kappa = 1.4, bT = -6.5e-3 K/m, T0 = 288.15 K, p0 = 101325 Pa, g0 = 9.80665.
namespace gdnav::core::atm {

constexpr double kR_JpkgK = 287.05287;
constexpr double kKappa = 1.4;
constexpr double kBetaT_Kpm = -6.5e-3;
constexpr double kT0_K = 288.15;
constexpr double kP0_Pa = 101325.0;
constexpr double kG0_mps2 = 9.80665;
constexpr double kRho0_kgpm3 = kP0_Pa / (kR_JpkgK * kT0_K);

double pressure_Pa(double Hp_m);
double pressure_altitude_m(double p_Pa);
double dp_dHp_Papm(double Hp_m);  // dp/dHp
constexpr double temperature_isa_K(double Hp_m) { return kT0_K + kBetaT_Kpm * Hp_m; }
constexpr double temperature_K(double Hp_m, double dT_K) { return kT0_K + dT_K + kBetaT_Kpm * Hp_m; }
constexpr double density_kgpm3(double p_Pa, double T_K) { return p_Pa / (kR_JpkgK * T_K); }
double speed_of_sound_mps(double T_K);

double pressure_altitude_msl_m(double dp_Pa);
double geopotential_altitude_m(double Hp_m, double dT_K, double dp_Pa);
// Newton from `Hp_guess_m` (any finite value; NaN = start from H + Hp_MSL, exact when dT = 0).
double pressure_altitude_from_geopotential_m(double H_m, double dT_K, double dp_Pa,
                                             double Hp_guess_m = std::numeric_limits<double>::quiet_NaN());

// Inverse helpers: offsets from observed quantities.
constexpr double temperature_offset_K(double T_K, double Hp_m) { return T_K - temperature_isa_K(Hp_m); }
double pressure_offset_Pa(double dT_K, double Hp_m, double H_m);

// Pitot tube: total pressure from true airspeed and back.
double total_pressure_Pa(double tas_mps, double p_Pa, double T_K);
double tas_from_total_pressure_mps(double pt_Pa, double p_Pa, double T_K);

// Same, with Hp_MSL = pressure_altitude_msl_m(dp) given (lets a caller cache it while dp is constant).
double pressure_altitude_from_geopotential_msl_m(double H_m, double dT_K, double Hp_msl_m, double Hp_guess_m);

// Everything the physics needs at one geopotential altitude.
struct AirProperties {
    double Hp_m{0.0};
    double H_m{0.0};
    double p_Pa{0.0};
    double T_K{0.0};
    double rho_kgpm3{0.0};
    double a_mps{0.0};
};
AirProperties air_properties(double H_m, double dT_K, double dp_Pa,
                             double Hp_guess_m = std::numeric_limits<double>::quiet_NaN());
AirProperties air_properties_msl(double H_m, double dT_K, double Hp_msl_m, double Hp_guess_m);

}  // namespace gdnav::core::atm
namespace gdnav { namespace atm = core::atm; }  // the short name (docs/architecture.md, "Namespaces")
