#include "earth/wgs84.hpp"

#include <GeographicLib/Geocentric.hpp>
#include <cmath>

namespace gdnav::core::earth {

Radii radii_sc(double s, double c) {
    Radii r;
    r.n_m = wgs84::kA_m / std::sqrt(1.0 - wgs84::kE2 * s * s);
    r.m_m = r.n_m / (1.0 + wgs84::kEp2 * c * c);
    return r;
}

Radii radii(double lat_rad) { return radii_sc(std::sin(lat_rad), std::cos(lat_rad)); }

Vec3 ecef_from_geodetic(const Geodetic& p) {
    Vec3 r;
    GeographicLib::Geocentric::WGS84().Forward(math::rad2deg(p.lat_rad), math::rad2deg(p.lon_rad), p.h_m, r.x(), r.y(),
                                               r.z());
    return r;
}

Geodetic geodetic_from_ecef(const Vec3& r_e_m) {
    double lat_deg = 0.0, lon_deg = 0.0, h = 0.0;
    GeographicLib::Geocentric::WGS84().Reverse(r_e_m.x(), r_e_m.y(), r_e_m.z(), lat_deg, lon_deg, h);
    return {math::deg2rad(lon_deg), math::deg2rad(lat_deg), h};
}

Mat3 dcm_ecef_from_ned(double lon_rad, double lat_rad) {
    const double sl = std::sin(lon_rad), cl = std::cos(lon_rad);
    const double sp = std::sin(lat_rad), cp = std::cos(lat_rad);
    Mat3 r;
    // columns: north, east, down unit vectors expressed in ECEF
    r << -sp * cl, -sl, -cp * cl,  //
        -sp * sl, cl, -cp * sl,    //
        cp, 0.0, -sp;
    return r;
}

Vec3 position_rate_sc(const Radii& r, double c, double h_m, const Vec3& v) {
    return {v.y() / ((r.n_m + h_m) * c), v.x() / (r.m_m + h_m), -v.z()};
}

Vec3 position_rate(const Radii& r, double lat_rad, double h_m, const Vec3& v) {
    return position_rate_sc(r, std::cos(lat_rad), h_m, v);
}

Vec3 position_rate(double lat_rad, double h_m, const Vec3& v) { return position_rate(radii(lat_rad), lat_rad, h_m, v); }

Vec3 earth_rate_n_sc(double s, double c) { return {wgs84::kOmegaIE_rps * c, 0.0, -wgs84::kOmegaIE_rps * s}; }

Vec3 earth_rate_n(double lat_rad) { return earth_rate_n_sc(std::sin(lat_rad), std::cos(lat_rad)); }

Vec3 transport_rate_n_sc(const Radii& r, double s, double c, double h_m, const Vec3& v) {
    const double nh = r.n_m + h_m;
    return {v.y() / nh, -v.x() / (r.m_m + h_m), -v.y() * (s / c) / nh};
}

Vec3 transport_rate_n(const Radii& r, double lat_rad, double h_m, const Vec3& v) {
    return transport_rate_n_sc(r, std::sin(lat_rad), std::cos(lat_rad), h_m, v);
}

Vec3 transport_rate_n(double lat_rad, double h_m, const Vec3& v) {
    return transport_rate_n(radii(lat_rad), lat_rad, h_m, v);
}

Vec3 coriolis_n(double lat_rad, const Vec3& v) { return 2.0 * earth_rate_n(lat_rad).cross(v); }

}  // namespace gdnav::core::earth
