#include "denied_rules.hpp"

#include <cmath>

#include "math/rotation.hpp"
#include "nav_earth.hpp"

namespace gdnav::nav::denied {

Vec3 vtas_dot_body(double v, double a, double b, double vd, double ad, double bd) {
    const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
    return {vd * ca * cb - ad * v * sa * cb - bd * v * ca * sb,  //
            vd * sb + bd * v * cb,                               //
            vd * sa * cb + ad * v * ca * cb - bd * v * sa * sb};
}

Eigen::Matrix3d vtas_jacobian(double tas, double aoa, double aos) {
    Eigen::Matrix3d j;
    j << vtas_dot_body(tas, aoa, aos, 1.0, 0.0, 0.0), vtas_dot_body(tas, aoa, aos, 0.0, 1.0, 0.0),
        vtas_dot_body(tas, aoa, aos, 0.0, 0.0, 1.0);
    return j;
}

Vec3 ground_accel_n(const Quat& q_nb, const Vec3& f_b, double lat, double h, const Vec3& v) {
    return q_nb * f_b - earth::w_en_n(lat, h, v).cross(v) + earth::gravity_n(lat, h) - earth::a_cor_n(lat, v);
}

double altitude_from_pressure(double hp, double dt, double dp) {
    return earth::h_from_H(earth::H_from_Hp(hp, dt, dp));
}

DeniedState step(const DeniedState& prev, const DeniedInputs& in, double dt, HorizontalRule hor, VerticalRule ver) {
    const AirDataEstimate& air = in.air;
    const Vec3 vtas_b = math::vtas_body(air.tas_mps, air.aoa_rad, air.aos_rad);
    const Vec3 vtas_n = in.q_nb * vtas_b;
    DeniedState s = prev;
    switch (hor) {
        case HorizontalRule::kFrozenWind:
            s.v_n_mps = prev.wind_n_mps + vtas_n;
            break;
        case HorizontalRule::kDoubleIntegration:
            s.v_n_mps = prev.v_n_mps + dt * ground_accel_n(in.q_nb, in.f_b_mps2, prev.lat_rad, prev.h_m, prev.v_n_mps);
            s.wind_n_mps = s.v_n_mps - vtas_n;
            break;
        case HorizontalRule::kWindIntegration: {
            const Vec3 vdot = ground_accel_n(in.q_nb, in.f_b_mps2, prev.lat_rad, prev.h_m, prev.v_n_mps);
            const Vec3 vtas_dot_b =
                vtas_dot_body(air.tas_mps, air.aoa_rad, air.aos_rad, air.tas_dot_mps2, air.aoa_dot_rps, air.aos_dot_rps);
            const Vec3 vtas_dot_n = in.q_nb * Vec3(vtas_dot_b + in.w_nb_b_rps.cross(vtas_b));
            s.wind_n_mps = prev.wind_n_mps + dt * (vdot - vtas_dot_n);
            s.v_n_mps = s.wind_n_mps + vtas_n;
            break;
        }
    }
    switch (ver) {
        case VerticalRule::kPressure:
            s.h_m = altitude_from_pressure(air.Hp_m, air.dT_K, prev.dp_Pa);
            break;
        case VerticalRule::kIntegration:
            s.h_m = prev.h_m - dt * s.v_n_mps.z();
            break;
        case VerticalRule::kAirspeedIntegration:
            s.wind_n_mps.z() = 0.0;
            s.v_n_mps.z() = vtas_n.z();
            s.h_m = prev.h_m - dt * s.v_n_mps.z();
            break;
    }
    const earth::Radii r = earth::radii(prev.lat_rad);
    s.lon_rad = math::wrap_pi(prev.lon_rad + dt * s.v_n_mps.y() / ((r.n_m + s.h_m) * std::cos(prev.lat_rad)));
    s.lat_rad = prev.lat_rad + dt * s.v_n_mps.x() / (r.m_m + s.h_m);
    return s;
}

}  // namespace gdnav::nav::denied
