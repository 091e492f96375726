#include "flight_physics/model/dynamics.hpp"

#include <algorithm>
#include <cmath>

namespace gdnav::physics {

Dynamics::Dynamics(const AircraftModel& aircraft, const earth::EarthTruthParams& earth_truth)
    : aircraft_(aircraft), gravity_(earth_truth) {}

Controls Dynamics::clamp(const Controls& u) const {
    const ControlLimits& l = aircraft_.limits;
    return {std::clamp(u.throttle, 0.0, 1.0), std::clamp(u.elevator_rad, -l.elevator_rad, l.elevator_rad),
            std::clamp(u.aileron_rad, -l.aileron_rad, l.aileron_rad),
            std::clamp(u.rudder_rad, -l.rudder_rad, l.rudder_rad)};
}

void Dynamics::evaluate(const PhysicsState& x, const Controls& u, const Vec3& wind_n, const Vec3& turb_b,
                        const atm::Offsets& offsets, DynamicsWarmStart& warm, DynamicsEval& e) const {
    // Earth geometry and rates.
    const double s_lat = std::sin(x.lat_rad), c_lat = std::cos(x.lat_rad);
    const earth::Radii rad = earth::radii_sc(s_lat, c_lat);
    e.pos_rate = earth::position_rate_sc(rad, c_lat, x.h_m, x.v_n_mps);
    const Vec3 w_ie_n = earth::earth_rate_n_sc(s_lat, c_lat);
    const Vec3 w_en_n = earth::transport_rate_n_sc(rad, s_lat, c_lat, x.h_m, x.v_n_mps);
    e.r_nb = x.q_nb.toRotationMatrix();
    e.w_nb_b = x.w_ib_b_rps - e.r_nb.transpose() * (w_ie_n + w_en_n);

    // Air data.
    const double H = earth::geopotential_from_geometric(x.h_m);
    if (!(offsets.dp_Pa == warm.dp_Pa)) {
        warm.dp_Pa = offsets.dp_Pa;
        warm.hp_msl_m = atm::pressure_altitude_msl_m(offsets.dp_Pa);
    }
    e.atm = atm::air_properties_msl(H, offsets.dT_K, warm.hp_msl_m, warm.hp_m);
    warm.hp_m = e.atm.Hp_m;
    const Vec3 vtas_b = e.r_nb.transpose() * (x.v_n_mps - wind_n) - turb_b;
    e.air = math::air_angles(vtas_b);
    const double V = e.air.tas_mps;

    // Gravity.
    e.g_model_n = Vec3(0.0, 0.0, earth::normal_gravity_sin2_mps2(s_lat * s_lat, x.h_m));
    e.g_true_n = gravity_.apply(e.g_model_n);

    // Mass properties.
    const AircraftModel& ac = aircraft_;
    const Mat3 inertia = ac.mass.inertia_kgm2(x.mass_kg);
    const Vec3 dcg = ac.mass.cg_m(x.mass_kg) - ac.mass.cg_full_m;

    // Aerodynamics.
    const Geometry& g = ac.geometry;
    const double qbar_s = 0.5 * e.atm.rho_kgpm3 * V * V * g.wing_area_m2;
    const double inv_2v = V > 1e-6 ? 1.0 / (2.0 * V) : 0.0;
    const AeroCoefficients c = ac.aero.coefficients(e.air.aoa_rad, e.air.aos_rad, e.w_nb_b.x() * g.span_m * inv_2v,
                                                    e.w_nb_b.y() * g.chord_m * inv_2v, e.w_nb_b.z() * g.span_m * inv_2v,
                                                    u.elevator_rad, u.aileron_rad, u.rudder_rad);
    e.force_aero_b = qbar_s * Vec3(c.cx, c.cy, c.cz);
    const Vec3 m_aero = qbar_s * Vec3(g.span_m * c.cl, g.chord_m * c.cm, g.span_m * c.cn);

    // Propulsion.
    e.prop = ac.propulsion.compute(u.throttle, V, e.atm.rho_kgpm3, e.atm.p_Pa, e.atm.T_K, warm.prop_rps);
    warm.prop_rps = e.prop.speed_rps;

    // Translational dynamics.
    const Vec3 force_b = e.force_aero_b + Vec3(e.prop.thrust_N, 0.0, 0.0);
    e.f_ib_b = force_b / x.mass_kg;
    e.v_dot_n = e.r_nb * e.f_ib_b + e.g_true_n - (2.0 * w_ie_n + w_en_n).cross(x.v_n_mps);

    // Rotational dynamics.
    e.moment_b = m_aero + e.force_aero_b.cross(dcg) + Vec3(e.prop.torque_x_Nm, 0.0, 0.0);
    const Vec3& w = x.w_ib_b_rps;
    e.w_dot_ib_b = inertia.inverse() * (e.moment_b - w.cross(inertia * w));
    e.mass_rate_kgps = e.prop.mass_rate_kgps;
}

}  // namespace gdnav::physics
