#pragma once
// Aircraft description loaded from our YAML format (config/aircraft/mugin.yaml):
//   geometry (S, c, b), mass properties varying linearly with the fuel ratio, aerodynamics (aerodynamics.hpp),
//   propulsion (propulsion.hpp) and control-surface limits.
// Fuel ratio r = (m_full - m) / (m_full - m_empty) in [0, 1]; CG(r) and I(r) interpolate linearly between the
// full-tank and empty-tank values (r is clamped to [0, 1]). The inertia matrix is used as I in h = I w (so its
// xz element is -J_xz).
// Every value is range-checked and unknown keys are rejected: a bad file throws config::ConfigError naming the key.
#include <filesystem>
#include <string>

#include "config/config.hpp"
#include "flight_physics/model/aerodynamics.hpp"
#include "flight_physics/model/propulsion.hpp"
#include "math/rotation.hpp"

namespace gdnav::physics {

struct Geometry {
    double wing_area_m2{0.0};
    double chord_m{0.0};
    double span_m{0.0};
};

struct MassProperties {
    double full_kg{0.0};
    double empty_kg{0.0};
    math::Vec3 cg_full_m{math::Vec3::Zero()};  // body axes, from the reference point
    math::Vec3 cg_empty_m{math::Vec3::Zero()};
    math::Mat3 inertia_full_kgm2{math::Mat3::Zero()};
    math::Mat3 inertia_empty_kgm2{math::Mat3::Zero()};

    [[nodiscard]] double fuel_ratio(double mass_kg) const;
    [[nodiscard]] math::Vec3 cg_m(double mass_kg) const;
    [[nodiscard]] math::Mat3 inertia_kgm2(double mass_kg) const;
};

struct ControlLimits {
    double elevator_rad{0.0};
    double aileron_rad{0.0};
    double rudder_rad{0.0};
};

struct AircraftModel {
    std::string name;
    Geometry geometry;
    MassProperties mass;
    Aerodynamics aero;
    Propulsion propulsion;
    ControlLimits limits;

    // Reads a whole aircraft file (calls finish(): unknown keys are errors).
    static AircraftModel load(const std::filesystem::path& file);
    static AircraftModel from_config(const config::Config& cfg);  // reads and finishes `cfg`
};

}  // namespace gdnav::physics
