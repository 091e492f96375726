// Adapters from the navigation filters to the shared toolkits (see nav_earth.hpp); only the Jacobians' partial
// derivatives are computed here.
#include "nav_earth.hpp"

#include <cmath>

#include "earth/gravity.hpp"
#include "earth/magnetic.hpp"
#include "math/rotation.hpp"

namespace gdnav::nav::earth {

namespace ge = ::gdnav::earth;
namespace ga = ::gdnav::atm;

Radii radii(double lat) {
    const ge::Radii shared = ge::radii(lat);
    const double s = std::sin(lat), c = std::cos(lat);
    const double d = 1.0 - kE2 * s * s;
    Radii r;
    r.n_m = shared.n_m;
    r.m_m = shared.m_m;
    r.dn_dlat = r.n_m * kE2 * s * c / d;
    r.dm_dlat = 3.0 * r.m_m * kE2 * s * c / d;
    return r;
}

Gravity normal_gravity(double lat, double h) {
    // g(lat, h) = g_msl(lat) * fac(lat, h), fac = 1 - c1(lat) h + 3 h^2 / a^2 (common/core/earth/gravity.hpp).
    const double s = std::sin(lat), c = std::cos(lat);
    const double d = 1.0 - kE2 * s * s;
    const double g_msl = ge::normal_gravity_msl_mps2(lat);
    const double dg_msl = kGe_mps2 * s * c * (2.0 * ge::wgs84::kK * d + kE2 * (1.0 + ge::wgs84::kK * s * s)) / (d * std::sqrt(d));
    const double c1 = (2.0 / kA_m) * (1.0 + kF + ge::wgs84::kM - 2.0 * kF * s * s);
    const double fac = 1.0 - c1 * h + 3.0 * h * h / (kA_m * kA_m);
    Gravity g;
    g.g_mps2 = ge::normal_gravity_mps2(lat, h);
    g.dg_dh = g_msl * (-c1 + 6.0 * h / (kA_m * kA_m));
    g.dg_dlat = dg_msl * fac + g_msl * (2.0 / kA_m) * (4.0 * kF * s * c) * h;
    return g;
}

Vec3 w_ie_n(double lat) { return ge::earth_rate_n(lat); }
Vec3 w_en_n(double lat, double h, const Vec3& v) { return ge::transport_rate_n(lat, h, v); }
Vec3 a_cor_n(double lat, const Vec3& v) { return ge::coriolis_n(lat, v); }

Vec3 geodetic_rates(double lat, double h, const Vec3& v) {
    const Vec3 r = ge::position_rate(lat, h, v);  // (lon_dot, lat_dot, h_dot)
    return r;
}

double pressure_from_Hp(double hp) { return ga::pressure_Pa(hp); }
double Hp_from_pressure(double p) { return ga::pressure_altitude_m(p); }
double dpressure_dHp(double hp) { return ga::dp_dHp_Papm(hp); }
double dT_from(double t, double hp) { return ga::temperature_offset_K(t, hp); }
double H_from_Hp(double hp, double dt, double dp) { return ga::geopotential_altitude_m(hp, dt, dp); }
double dp_from_H(double h_geo, double hp, double dt) { return ga::pressure_offset_Pa(dt, hp, h_geo); }
double H_from_h(double h) { return ge::geopotential_from_geometric(h); }
double h_from_H(double hg) { return ge::geometric_from_geopotential(hg); }

// The filter's onboard WMM (1 Jan 2018, 3000 m) at the four corners of the area around lon 270..271 deg,
// lat 44..45 deg (docs/navigation.md "Onboard Earth/atmosphere"), interpolated by the shared model.
Vec3 magnetic_model_n(double lon, double lat) {
    static const ge::MagneticModel model([] {
        ge::MagneticCorners c;
        c.lat_min_rad = math::deg2rad(44.0);
        c.lat_max_rad = math::deg2rad(45.0);
        c.lon_min_rad = math::deg2rad(-90.0);
        c.lon_max_rad = math::deg2rad(-89.0);
        c.b_ll_nT = Vec3(17983.9, -739.1, 51571.5);
        c.b_lr_nT = Vec3(17977.2, -997.0, 51538.4);
        c.b_ul_nT = Vec3(17455.7, -764.6, 52192.7);
        c.b_ur_nT = Vec3(17449.5, -1019.6, 52158.5);
        return c;
    }());
    return model.field_n_nT(lat, lon);
}

}  // namespace gdnav::nav::earth
