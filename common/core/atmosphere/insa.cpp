#include "atmosphere/insa.hpp"

#include <cmath>
#include <stdexcept>

namespace gdnav::core::atm {

namespace {
constexpr double kExpP = -kG0_mps2 / (kR_JpkgK * kBetaT_Kpm);  // exponent of p(Hp), about 5.2559
constexpr double kExpHp = 1.0 / kExpP;
constexpr double kTolHp_m = 1e-9;
constexpr double kTolHpNewton_m = 1e-3;  // Newton on H(Hp): error after a step s is below 1e-6 s^2
constexpr int kMaxIter = 50;
}  // namespace

double pressure_Pa(double Hp_m) { return kP0_Pa * std::pow(1.0 + kBetaT_Kpm * Hp_m / kT0_K, kExpP); }

double pressure_altitude_m(double p_Pa) { return kT0_K / kBetaT_Kpm * (std::pow(p_Pa / kP0_Pa, kExpHp) - 1.0); }

double dp_dHp_Papm(double Hp_m) { return -kG0_mps2 * pressure_Pa(Hp_m) / (kR_JpkgK * temperature_isa_K(Hp_m)); }

double speed_of_sound_mps(double T_K) { return std::sqrt(kKappa * kR_JpkgK * T_K); }

double pressure_altitude_msl_m(double dp_Pa) { return pressure_altitude_m(kP0_Pa + dp_Pa); }

double geopotential_altitude_m(double Hp_m, double dT_K, double dp_Pa) {
    const double hp_msl = pressure_altitude_msl_m(dp_Pa);
    return Hp_m - hp_msl + dT_K / kBetaT_Kpm * std::log(temperature_isa_K(Hp_m) / temperature_isa_K(hp_msl));
}

namespace {
// Newton on f(Hp) = H(Hp) - H with f' = T / T_ISA, given Hp_MSL.
double solve_hp(double H_m, double dT_K, double hp_msl, double hp) {
    const double t_msl = temperature_isa_K(hp_msl);
    for (int i = 0; i < kMaxIter; ++i) {
        const double t_isa = temperature_isa_K(hp);
        const double f = hp - hp_msl + dT_K / kBetaT_Kpm * std::log(t_isa / t_msl) - H_m;
        const double step = f * t_isa / (t_isa + dT_K);
        hp -= step;
        if (std::abs(step) < kTolHpNewton_m) return hp;
    }
    throw std::runtime_error("atm: pressure altitude iteration did not converge");
}
}  // namespace

double pressure_altitude_from_geopotential_msl_m(double H_m, double dT_K, double hp_msl, double Hp_guess_m) {
    if (dT_K == 0.0) return H_m + hp_msl;  // exact
    const double hp0 = std::isnan(Hp_guess_m) ? H_m + hp_msl : Hp_guess_m;
    return solve_hp(H_m, dT_K, hp_msl, hp0);
}

double pressure_altitude_from_geopotential_m(double H_m, double dT_K, double dp_Pa, double Hp_guess_m) {
    return pressure_altitude_from_geopotential_msl_m(H_m, dT_K, pressure_altitude_msl_m(dp_Pa), Hp_guess_m);
}

double pressure_offset_Pa(double dT_K, double Hp_m, double H_m) {
    // Solve g(x) = H - Hp + x - (dT/bT) ln[(T0 + bT Hp) / (T0 + bT x)] = 0 for x = Hp_MSL, g' = 1 + dT / T_ISA(x).
    double x = Hp_m - H_m;
    const double t_hp = temperature_isa_K(Hp_m);
    for (int i = 0; i < kMaxIter; ++i) {
        const double t_x = temperature_isa_K(x);
        const double g = H_m - Hp_m + x - dT_K / kBetaT_Kpm * std::log(t_hp / t_x);
        const double step = g / (1.0 + dT_K / t_x);
        x -= step;
        if (std::abs(step) < kTolHp_m) return pressure_Pa(x) - kP0_Pa;
    }
    throw std::runtime_error("atm: pressure offset iteration did not converge");
}

double total_pressure_Pa(double tas_mps, double p_Pa, double T_K) {
    const double mach = tas_mps / speed_of_sound_mps(T_K);
    return p_Pa * std::pow(1.0 + 0.5 * (kKappa - 1.0) * mach * mach, kKappa / (kKappa - 1.0));
}

double tas_from_total_pressure_mps(double pt_Pa, double p_Pa, double T_K) {
    const double rho = density_kgpm3(p_Pa, T_K);
    return std::sqrt(2.0 * kKappa / (kKappa - 1.0) * p_Pa / rho *
                     (std::pow(pt_Pa / p_Pa, (kKappa - 1.0) / kKappa) - 1.0));
}

AirProperties air_properties(double H_m, double dT_K, double dp_Pa, double Hp_guess_m) {
    return air_properties_msl(H_m, dT_K, pressure_altitude_msl_m(dp_Pa), Hp_guess_m);
}

AirProperties air_properties_msl(double H_m, double dT_K, double Hp_msl_m, double Hp_guess_m) {
    AirProperties a;
    a.H_m = H_m;
    a.Hp_m = pressure_altitude_from_geopotential_msl_m(H_m, dT_K, Hp_msl_m, Hp_guess_m);
    a.p_Pa = pressure_Pa(a.Hp_m);
    a.T_K = temperature_K(a.Hp_m, dT_K);
    a.rho_kgpm3 = density_kgpm3(a.p_Pa, a.T_K);
    a.a_mps = speed_of_sound_mps(a.T_K);
    return a;
}

}  // namespace gdnav::core::atm
