#pragma once
// Plain input (truth) and output (measurement) structs of the sensor models. Every truth field maps one-to-one to
// a field of the IDL topic gdnav::msg::Truth (idl/gdnav.idl); every measurement struct carries the fields of the
// matching IDL sample topic (ImuSample, MagSample, AirSample, AtmSample, GnssSample) plus, where useful, the
// sensor's "full error" without white noise (truth for the filters' initialisation, docs/sensors.md, "Pre-flight
// fine alignment", and for the recorder's metrics). Frames: N = local NED, B = body; SI units.
#include <cstdint>

#include "math/rotation.hpp"

namespace gdnav::sensors {

using math::Mat3;
using math::Quat;
using math::Vec3;

// ------------------------------------------------------------------ inertial (gyroscopes + accelerometers)
struct InertialTruth {
    Vec3 f_ib_b_mps2{Vec3::Zero()};    // Truth.f_ib_b_mps2: specific force at the CG (aero + thrust) / mass
    Vec3 w_ib_b_rps{Vec3::Zero()};     // Truth.w_ib_b_rps: inertial angular rate
    Vec3 dw_ib_b_rps2{Vec3::Zero()};   // Truth.dw_ib_b_rps2: inertial angular acceleration
    double mass_kg{0.0};               // Truth.mass_kg: sets the CG position (lever arm); clamped to [empty, full]
};

struct ImuMeasurement {                // -> ImuSample
    std::uint64_t step{0};
    double t_s{0.0};
    Vec3 f_b_mps2{Vec3::Zero()};       // measured specific force, body axes as estimated by the platform
    Vec3 w_b_rps{Vec3::Zero()};        // measured inertial angular rate
    Vec3 e_acc_mps2{Vec3::Zero()};     // full accelerometer error E_acc = f_b - f_ib_b - white noise
    Vec3 e_gyr_rps{Vec3::Zero()};      // full gyroscope error E_gyr = w_b - w_ib_b - white noise
};

// ------------------------------------------------------------------ magnetometers
struct MagTruth {
    Quat q_nb{Quat::Identity()};       // Truth.q_nb: body -> NED attitude
    Vec3 b_n_nT{Vec3::Zero()};         // Truth.b_n_nT: TRUE magnetic field in N (not the model field)
};

struct MagMeasurement {                // -> MagSample
    std::uint64_t step{0};
    double t_s{0.0};
    Vec3 b_b_nT{Vec3::Zero()};         // measured magnetic field in B
    Vec3 e_mag_nT{Vec3::Zero()};       // full error E_mag = hard iron + offset + M_m b_b (no white noise)
};

// ------------------------------------------------------------------ Pitot tube and vanes
struct AirTruth {
    double tas_mps{0.0};               // Truth.tas_mps
    double aoa_rad{0.0};               // Truth.aoa_rad
    double aos_rad{0.0};               // Truth.aos_rad
};

struct AirMeasurement {                // -> AirSample
    std::uint64_t step{0};
    double t_s{0.0};
    double tas_mps{0.0};
    double aoa_rad{0.0};
    double aos_rad{0.0};
};

// ------------------------------------------------------------------ barometer and thermometer
struct AtmTruth {
    double p_Pa{0.0};                  // Truth.p_Pa: static pressure
    double T_K{0.0};                   // Truth.T_K: static temperature
};

struct AtmMeasurement {                // -> AtmSample
    std::uint64_t step{0};
    double t_s{0.0};
    double p_Pa{0.0};
    double T_K{0.0};
};

// ------------------------------------------------------------------ GNSS receiver
struct GnssTruth {
    double lon_rad{0.0};               // Truth.lon_rad (WGS84 geodetic)
    double lat_rad{0.0};               // Truth.lat_rad
    double h_m{0.0};                   // Truth.h_m (ellipsoidal height)
    Vec3 v_n_mps{Vec3::Zero()};        // Truth.v_n_mps: ground velocity in N
};

struct GnssMeasurement {               // -> GnssSample
    std::uint64_t step{0};
    double t_s{0.0};
    bool fix_valid{false};             // true only on fix epochs while signals exist
    // On fix epochs: the new fix. Between fixes and after the signal loss: the last fix, unchanged (all zero
    // before the first fix). Consumers must use fix_valid.
    double lon_rad{0.0};
    double lat_rad{0.0};
    double h_m{0.0};
    Vec3 v_n_mps{Vec3::Zero()};
    Vec3 pos_err_n_m{Vec3::Zero()};    // position error of the held fix in N at the true fix position [m]
    Vec3 iono_err_n_m{Vec3::Zero()};   // its ionospheric part [m]
};

}  // namespace gdnav::sensors
