#include "flight_physics/model/aircraft_model.hpp"

#include <algorithm>

namespace gdnav::physics {

double MassProperties::fuel_ratio(double m) const { return std::clamp((full_kg - m) / (full_kg - empty_kg), 0.0, 1.0); }

math::Vec3 MassProperties::cg_m(double m) const {
    const double r = fuel_ratio(m);
    return cg_full_m + r * (cg_empty_m - cg_full_m);
}

math::Mat3 MassProperties::inertia_kgm2(double m) const {
    const double r = fuel_ratio(m);
    return inertia_full_kgm2 + r * (inertia_empty_kgm2 - inertia_full_kgm2);
}

namespace {
math::Mat3 read_inertia(const config::Config& c, const char* key) {
    const math::Mat3 i = c.get_mat3(key, config::Range{-1e4, 1e4});
    if (!i.isApprox(i.transpose(), 1e-12)) c.fail(key, "must be symmetric");
    const Eigen::SelfAdjointEigenSolver<math::Mat3> es(i);
    const auto ev = es.eigenvalues();
    if (!(ev.minCoeff() > 0.0)) c.fail(key, "must be positive definite");
    // Triangle inequality of principal moments (physical rigid body).
    if (ev(0) + ev(1) < ev(2)) c.fail(key, "principal moments violate the triangle inequality");
    return i;
}
}  // namespace

AircraftModel AircraftModel::from_config(const config::Config& c) {
    using config::Range;
    AircraftModel a;
    a.name = c.get_string("name");

    const config::Config g = c.child("geometry");
    a.geometry.wing_area_m2 = g.get_double("wing_area_m2", Range{1e-3, 1e3});
    a.geometry.chord_m = g.get_double("chord_m", Range{1e-3, 1e2});
    a.geometry.span_m = g.get_double("span_m", Range{1e-3, 1e2});

    const config::Config m = c.child("mass");
    a.mass.full_kg = m.get_double("full_kg", Range{1e-3, 1e6});
    a.mass.empty_kg = m.get_double("empty_kg", Range{1e-3, 1e6});
    if (!(a.mass.empty_kg < a.mass.full_kg)) m.fail("empty_kg", "must be smaller than full_kg");
    a.mass.cg_full_m = m.get_vec3("cg_full_m", Range{-10.0, 10.0});
    a.mass.cg_empty_m = m.get_vec3("cg_empty_m", Range{-10.0, 10.0});
    a.mass.inertia_full_kgm2 = read_inertia(m, "inertia_full_kgm2");
    a.mass.inertia_empty_kgm2 = read_inertia(m, "inertia_empty_kgm2");

    a.aero = Aerodynamics::from_config(c.child("aerodynamics"));
    a.propulsion = Propulsion::from_config(c.child("propulsion"));

    const config::Config l = c.child("control_limits");
    a.limits.elevator_rad = l.get_angle_deg("elevator_deg", Range{0.1, 45.0});
    a.limits.aileron_rad = l.get_angle_deg("aileron_deg", Range{0.1, 45.0});
    a.limits.rudder_rad = l.get_angle_deg("rudder_deg", Range{0.1, 45.0});
    c.finish();
    return a;
}

AircraftModel AircraftModel::load(const std::filesystem::path& file) { return from_config(config::Config::load(file)); }

}  // namespace gdnav::physics
