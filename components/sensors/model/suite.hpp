#pragma once
// Sensor suite configuration: which grade each sensor group uses plus the settings that are not part of a grade
// (inertial bias-drift band, IMU mounting, sample timing, GNSS signal loss). A suite file names one grade per group:
//
//     sample_period_s: 0.01          # sensor step dt (one lockstep tick)
//     start_time_s: -50.0            # t0: time of step k = 0
//     bias_drift_band: 100           # N: inertial bias drift held in +-N sigma_u sqrt(dt) (paper: 100, 300, 1000)
//     gyroscopes:     {grade: baseline}
//     accelerometers: {grade: baseline}
//     magnetometers:  {grade: baseline}
//     air_data:       {grade: baseline}     # Pitot tube + AOA/AOS vanes
//     atmospheric:    {grade: baseline}     # barometer + thermometer
//     gnss:           {grade: baseline, loss_time_s: 100.0}   # omit loss_time_s: never lost
//     platform: {...}                       # IMU mounting, see PlatformParams
//     alignment: {...}                      # pre-flight fine alignment errors, see AlignmentErrors (alignment.hpp)
//
// Grade `g` of group `G` is read from <grades_dir>/<G>/<g>.yaml (grades_dir = the suite file's folder unless the
// suite sets `grades_dir`, relative to itself). Switching a grade is a one-word edit of the suite file.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "config/config.hpp"
#include "math/rotation.hpp"
#include "gnc/alignment.hpp"
#include "sensors/model/grades.hpp"

namespace gdnav::sensors {

// IMU mounting (docs/sensors.md, "IMU mounting"). Positions relative to the reference point R (wing trailing
// edge) in body axes; Euler angles 3-2-1 of the body -> platform rotation (R_BP maps platform to body axes).
struct PlatformParams {
    math::Vec3 imu_position_m{0.30, 0.0, 0.10};          // true T_RP
    double imu_position_error_m{0.01};                   // sigma per axis of T_RP,est - T_RP,true
    math::Vec3 mounting_sigma_rad{math::Vec3::Zero()};   // sigma of the true (yaw, pitch, bank) body -> platform
    double mounting_estimate_error_rad{0.0};             // sigma per angle of estimated - true mounting
    math::Vec3 cg_full_m{0.207, 0.0, -0.005};            // CG T_RB at full tank
    math::Vec3 cg_empty_m{0.219, 0.0, -0.006};           // CG T_RB at empty tank
    double mass_full_kg{19.715};
    double mass_empty_kg{17.835};
    bool operator==(const PlatformParams&) const = default;
};

struct InertialParams {
    TriadGrade gyr;
    TriadGrade acc;
    double bias_drift_band{100.0};  // N [steps of sigma_u sqrt(dt)], both triads
    PlatformParams platform;
    double dt_s{0.01};
    bool operator==(const InertialParams&) const = default;
};

struct MagParams {
    MagGrade grade;
    double dt_s{0.01};
    bool operator==(const MagParams&) const = default;
};

struct AirParams {
    AirGrade grade;
    bool operator==(const AirParams&) const = default;
};

struct AtmParams {
    AtmGrade grade;
    bool operator==(const AtmParams&) const = default;
};

struct GnssParams {
    GnssGrade grade;
    double t0_s{0.0};                   // time of step 0
    double dt_s{0.01};                  // step
    std::optional<double> loss_time_s;  // t_GNSS: last fix at the last fix epoch <= t_GNSS; none: never lost
    bool operator==(const GnssParams&) const = default;
};

struct SensorSuiteParams {
    // Grade names as selected in the suite file (for logs and the recorder).
    std::string gyr_grade, acc_grade, mag_grade, air_grade, atm_grade, gnss_grade;
    InertialParams inertial;
    AlignmentErrors alignment;  // used by sensors_inertial (attitude, E_gyr, E_acc) and sensors_magnetic
    MagParams mag;
    AirParams air;
    AtmParams atm;
    GnssParams gnss;
};

// Loads a suite file and the grade files it names; throws config::ConfigError naming the file and key.
SensorSuiteParams load_sensor_suite(const std::filesystem::path& suite_file);
// Same for a suite mapping embedded elsewhere (e.g. a scenario's `sensors:` section).
SensorSuiteParams parse_sensor_suite(const config::Config& suite_cfg, const std::filesystem::path& grades_dir);
// Loads `<grades_dir>/<group>/<grade>.yaml`; an unknown grade names the file and lists the available grades.
config::Config load_grade_file(const std::filesystem::path& grades_dir, const std::string& group,
                               const std::string& grade);
// Reads the grade name at `key` of `section` (letters, digits, '_', '-') into `name` and loads that grade file; a bad
// or unknown grade is an error naming `key` (and listing the available grades).
config::Config load_grade(const config::Config& section, std::string_view key, const std::filesystem::path& grades_dir,
                          const std::string& group, std::string& name);
PlatformParams parse_platform(const config::Config& cfg);

// Every numeric parameter of a suite as (dotted name, SI value), in a fixed order, e.g. ("gyr.bias_offset",
// 3.49e-3). Used to log a run's sensor set and to compare two suites.
std::vector<std::pair<std::string, double>> list_parameters(const SensorSuiteParams& suite);

}  // namespace gdnav::sensors
