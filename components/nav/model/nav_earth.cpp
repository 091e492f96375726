// TO BE REPLACED by common/earth and common/atmosphere (see nav_earth.hpp).
#include "nav_earth.hpp"

#include <cmath>

#include "math/rotation.hpp"

namespace gdnav::nav::earth {

Radii radii(double lat) {
    const double s = std::sin(lat), c = std::cos(lat);
    const double d = 1.0 - kE2 * s * s;
    Radii r;
    r.n_m = kA_m / std::sqrt(d);
    r.m_m = kA_m * (1.0 - kE2) / (d * std::sqrt(d));
    r.dn_dlat = r.n_m * kE2 * s * c / d;
    r.dm_dlat = 3.0 * r.m_m * kE2 * s * c / d;
    return r;
}

Gravity normal_gravity(double lat, double h) {
    const double s = std::sin(lat), c = std::cos(lat);
    const double k = kB_m * kGp_mps2 / (kA_m * kGe_mps2) - 1.0;
    const double m = kWie_rps * kWie_rps * kA_m * kA_m * kB_m / kGM_m3ps2;
    const double d = 1.0 - kE2 * s * s;
    const double g_msl = kGe_mps2 * (1.0 + k * s * s) / std::sqrt(d);
    const double dg_msl = kGe_mps2 * s * c * (2.0 * k * d + kE2 * (1.0 + k * s * s)) / (d * std::sqrt(d));
    const double c1 = (2.0 / kA_m) * (1.0 + kF + m - 2.0 * kF * s * s);
    const double fac = 1.0 - c1 * h + 3.0 * h * h / (kA_m * kA_m);
    Gravity g;
    g.g_mps2 = g_msl * fac;
    g.dg_dh = g_msl * (-c1 + 6.0 * h / (kA_m * kA_m));
    g.dg_dlat = dg_msl * fac + g_msl * (2.0 / kA_m) * (4.0 * kF * s * c) * h;
    return g;
}

Vec3 w_ie_n(double lat) { return {kWie_rps * std::cos(lat), 0.0, -kWie_rps * std::sin(lat)}; }

Vec3 w_en_n(double lat, double h, const Vec3& v) {
    const Radii r = radii(lat);
    return {v.y() / (r.n_m + h), -v.x() / (r.m_m + h), -v.y() * std::tan(lat) / (r.n_m + h)};
}

Vec3 a_cor_n(double lat, const Vec3& v) { return 2.0 * w_ie_n(lat).cross(v); }

Vec3 geodetic_rates(double lat, double h, const Vec3& v) {
    const Radii r = radii(lat);
    return {v.y() / ((r.n_m + h) * std::cos(lat)), v.x() / (r.m_m + h), -v.z()};
}

namespace {
constexpr double kExpP = -kG0_mps2 / (kR_JpkgK * kBetaT_Kpm);  // ~ 5.2559
}

double pressure_from_Hp(double hp) { return kP0_Pa * std::pow(1.0 + kBetaT_Kpm * hp / kT0_K, kExpP); }

double Hp_from_pressure(double p) { return (kT0_K / kBetaT_Kpm) * (std::pow(p / kP0_Pa, 1.0 / kExpP) - 1.0); }

double dpressure_dHp(double hp) {
    return -kG0_mps2 * pressure_from_Hp(hp) / (kR_JpkgK * (kT0_K + kBetaT_Kpm * hp));
}

double dT_from(double t, double hp) { return t - (kT0_K + kBetaT_Kpm * hp); }

double H_from_Hp(double hp, double dt, double dp) {
    const double hp0 = Hp_from_pressure(kP0_Pa + dp);
    return hp - hp0 + (dt / kBetaT_Kpm) * std::log((kT0_K + kBetaT_Kpm * hp) / (kT0_K + kBetaT_Kpm * hp0));
}

// Solves H_from_Hp(Hp, dT, dp) = H for dp: Newton on Hp0 of
//   F(Hp0) = H - Hp + Hp0 - (dT/beta) ln[(T0 + beta Hp)/(T0 + beta Hp0)],  F'(Hp0) = 1 + dT/(T0 + beta Hp0),
// which is monotonic (F' > 0 for any realistic dT), started at Hp0 = Hp - H; converges in 2-3 iterations.
double dp_from_H(double h_geo, double hp, double dt) {
    double hp0 = hp - h_geo;
    for (int i = 0; i < 20; ++i) {
        const double f = h_geo - hp + hp0 -
                         (dt / kBetaT_Kpm) * std::log((kT0_K + kBetaT_Kpm * hp) / (kT0_K + kBetaT_Kpm * hp0));
        const double df = 1.0 + dt / (kT0_K + kBetaT_Kpm * hp0);
        const double step = f / df;
        hp0 -= step;
        if (std::abs(step) < 1e-9) break;
    }
    return pressure_from_Hp(hp0) - kP0_Pa;
}

double H_from_h(double h) { return kRE_m * h / (kRE_m + h); }
double h_from_H(double hg) { return kRE_m * hg / (kRE_m - hg); }

// WMM (1 Jan 2018, h = 3000 m) at the four corners of the "mix" area, NED nT (models-nav.md §9).
Vec3 magnetic_model_n(double lon, double lat) {
    const Vec3 b00(17983.9, -739.1, 51571.5);   // lon 270, lat 44
    const Vec3 b10(17977.2, -997.0, 51538.4);   // lon 271, lat 44
    const Vec3 b01(17455.7, -764.6, 52192.7);   // lon 270, lat 45
    const Vec3 b11(17449.5, -1019.6, 52158.5);  // lon 271, lat 45
    const double u = (math::rad2deg(math::wrap_2pi(lon)) - 270.0);  // fraction along lon (1 deg cell)
    const double v = (math::rad2deg(lat) - 44.0);                   // fraction along lat
    return (1.0 - u) * (1.0 - v) * b00 + u * (1.0 - v) * b10 + (1.0 - u) * v * b01 + u * v * b11;
}

}  // namespace gdnav::nav::earth
