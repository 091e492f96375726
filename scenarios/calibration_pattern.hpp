#pragma once
// The calibration pattern of the paper scenarios (generator option `calibration`): GNSS-aided manoeuvres flown
// before the paper's timeline so that the navigation filters can observe the biases that straight and level flight
// hides (docs/navigation.md, "In-flight alignment").
//
//   generator: {name: paper_scenario2, calibration: {pattern: turns, bank_deg: 20}}
//
// The pattern is flown from a new, earlier t0: the run starts `duration_s` earlier (run.t0_s decreases and
// run.duration_s or run.steps grows by it) and everything from the scenario file's t0 on is the paper's scenario
// (absolute times, the GNSS loss, the wind and offset ramps, the mission draws: the pattern draws nothing).
// Mission operations prepended to the drawn mission (bearing chi_0, airspeed V_ini, Hp_ini held throughout):
//   lead-in   hold chi_0 for lead_in_s
//   turns     bank +bank for a 360 deg turn (right), then -bank for a 360 deg turn (left)
//   s_turns   `cycles` times: bank +bank for amplitude, -bank for 2 amplitude, +bank for amplitude
//   settle    hold chi_0 (the drawn mission's first operation) until the file's t0
// Turn durations use the coordinated-turn rate g tan(bank) / V_ini; the bearing hold after the pattern takes out
// what roll-in and roll-out leave. duration_s = lead-in + pattern + settle_s, rounded up to a whole second.
#include <string>

#include <yaml-cpp/yaml.h>

#include "config/config.hpp"

namespace gdnav::scenario {

struct CalibrationPattern {
    enum class Kind { turns, s_turns } kind{Kind::turns};
    double bank_rad{0.0};
    double lead_in_s{20.0};
    double settle_s{30.0};
    int cycles{2};              // s_turns
    double amplitude_rad{0.0};  // s_turns: heading swing either side of chi_0
};

// Reads the `calibration` section (ranges in the header of calibration_pattern.cpp); throws config::ConfigError
// naming the file and key.
CalibrationPattern parse_calibration(const config::Config& c);

// Time the pattern adds before the file's t0 [s] (a whole number of seconds).
double calibration_duration_s(const CalibrationPattern& p, double airspeed_mps);

// The mission operations of the pattern (mission_yaml format), to go before the drawn mission's operations.
YAML::Node calibration_operations(const CalibrationPattern& p, double airspeed_mps, double pressure_altitude_m,
                                  double bearing_rad);

// One line for `gdnav scenario`.
std::string describe_calibration(const CalibrationPattern& p, double airspeed_mps);

}  // namespace gdnav::scenario
