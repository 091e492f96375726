#pragma once
// Sensor performance grades: the per-sensor error parameters of the paper's tables (Gallo & Barrientos,
// "Sensors" and "Influence of Sensor Quality" sections), one YAML file per grade in config/sensors/<group>/.
// Every value is held in SI units; the files use the paper's units (degrees for angles) and the parse
// functions convert. Each parse function reads a whole grade file (or an embedded mapping with the same keys),
// validates every value (sigmas >= 0) and calls finish(), so a typo or a missing key throws ConfigError naming the
// file and the key.
#include <string>

#include "config/config.hpp"

namespace gdnav::sensors {

// Gyroscope or accelerometer triad (paper table "GYR-ACC Baseline" and the GYR/ACC grade tables).
// Units: gyroscopes rad/s based, accelerometers m/s^2 based ("U" below).
struct TriadGrade {
    double bias_drift{0.0};      // sigma_u, bias-drift (random walk) density [U s^-0.5]
    double system_noise{0.0};    // sigma_v, white-noise density [U s^0.5]
    double scale_factor{0.0};    // s, sigma of each diagonal entry of the scale/cross-coupling matrix [-]
    double cross_coupling{0.0};  // m, sigma of each off-diagonal entry [-]
    double bias_offset{0.0};     // B0, sigma of the run-to-run bias offset per axis [U]
    bool operator==(const TriadGrade&) const = default;
};

// Magnetometer triad (paper tables "MAG Baseline", "MAG Better / Worse").
struct MagGrade {
    double system_noise_nT_rts{0.0};  // sigma_v [nT s^0.5]
    double scale_factor{0.0};         // s, scale factor and soft iron [-]
    double cross_coupling{0.0};       // m, cross coupling and soft iron [-]
    double hard_iron_nT{0.0};         // sigma of the hard-iron offset per axis [nT]
    double bias_offset_nT{0.0};       // B0 [nT]
    bool operator==(const MagGrade&) const = default;
};

// A single-axis sensor with a run-to-run bias offset and per-sample white noise. Both are standard deviations
// of the output itself (per sample, no sqrt(dt) scaling), as in the paper's air data tables.
struct ScalarGrade {
    double noise{0.0};        // sigma of the per-sample noise
    double bias_offset{0.0};  // B0, sigma of the run-to-run offset
    bool operator==(const ScalarGrade&) const = default;
};

// Pitot tube and air vanes (paper tables "Baseline airspeed and air data sensors", "TAS-AOA-AOS Better/Worse").
struct AirGrade {
    ScalarGrade tas_mps;  // true airspeed [m/s]
    ScalarGrade aoa_rad;  // angle of attack [rad]
    ScalarGrade aos_rad;  // angle of sideslip [rad]
    bool operator==(const AirGrade&) const = default;
};

// Barometer and thermometer (paper tables "Baseline ... air data sensors", "OSP-OAT Worse/Worst").
struct AtmGrade {
    ScalarGrade p_Pa;  // outside static pressure [Pa]
    ScalarGrade T_K;   // outside air temperature [K]
    bool operator==(const AtmGrade&) const = default;
};

// GNSS receiver (docs/sensors.md, "GNSS": the reference's only grade; the paper has no GNSS grade table).
struct GnssGrade {
    double horizontal_m{0.0};         // white position error sigma, North and East, per fix [m]
    double vertical_m{0.0};           // white position error sigma, Down, per fix [m]
    double velocity_mps{0.0};         // white velocity error sigma per NED axis, per fix [m/s]
    double iono_step_m{0.0};          // sigma_iono: ionospheric random-walk step [m]
    double iono_initial_steps{0.0};   // sigma of the initial ionospheric state, in walk steps [-]
    double iono_band_steps{0.0};      // soft band of the ionospheric walk, in walk steps [-]
    int iono_update_fixes{1};         // fixes between two ionospheric walk nodes [-]
    double fix_period_s{1.0};         // time between fixes [s]
    bool operator==(const GnssGrade&) const = default;
};

// Parse one grade file (or mapping). The file may hold an optional `description` string.
TriadGrade parse_gyro_grade(const config::Config& cfg);
TriadGrade parse_acc_grade(const config::Config& cfg);
MagGrade parse_mag_grade(const config::Config& cfg);
AirGrade parse_air_grade(const config::Config& cfg);
AtmGrade parse_atm_grade(const config::Config& cfg);
GnssGrade parse_gnss_grade(const config::Config& cfg);

}  // namespace gdnav::sensors
