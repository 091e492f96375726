#pragma once
// Missions from YAML (config/missions/*.yaml). Angles are degrees in the file (keys ending in _deg), SI inside.
//
//   name: scenario1_example
//   t_end_s: 3800
//   operations:
//     - op: hold                       # first operation: must be `hold` and set all four channels
//       throttle: {mode: airspeed, airspeed_mps: 29.13}
//       elevator: {mode: pressure_altitude, pressure_altitude_m: 2557.1}
//       aileron:  {mode: bearing, bearing_deg: -72}
//       rudder:   {mode: sideslip, sideslip_deg: 0}
//       until:    {trigger: time, t_s: 192.6}
//     - op: turn                       # 2 operations: bank, then hold the new bearing
//       to_bearing_deg: -56
//       bank_deg: 10                   # magnitude, (0, 30]
//       lead_deg: 5                    # optional (default 5): the bank ends this much before the target
//       direction: auto                # optional: auto (side of the shorter turn) | right | left
//       until: {trigger: elapsed, dt_s: 492}
//     - op: airspeed_change
//       to_airspeed_mps: 31.0
//       until: {trigger: elapsed, dt_s: 454}
//     - op: altitude_change            # 2 operations: air-path angle, then hold the new pressure altitude
//       to_pressure_altitude_m: 2811
//       path_angle_deg: 2              # magnitude, (0, 10]
//       direction: auto                # optional: auto | climb | descend
//       until: {trigger: end}
//
// `hold` may change any subset of channels; unnamed channels keep the previous operation's settings.
// Channel modes and their target keys:
//   throttle: airspeed (airspeed_mps)
//   elevator: pitch (pitch_deg), pressure_altitude (pressure_altitude_m), altitude (altitude_m),
//             air_path_angle (air_path_angle_deg)
//   aileron:  bank (bank_deg), bearing (bearing_deg), heading (heading_deg), air_bank (air_bank_deg),
//             air_bearing (air_bearing_deg)
//   rudder:   sideslip (sideslip_deg)
// Triggers (`until`): time (t_s), elapsed (dt_s), bearing (bearing_deg), heading (heading_deg),
//   pressure_altitude (pressure_altitude_m), altitude (altitude_m), path_angle (path_angle_deg),
//   airspeed (airspeed_mps), end.
// Every value is range-checked and unknown keys are rejected: config::ConfigError names the file and key.
#include <filesystem>

#include "config/config.hpp"
#include "gnc/mission.hpp"

namespace gdnav::core::gnc {

Mission load_mission(const std::filesystem::path& file);
// Reads a mission from a mapping (a whole file or a section of a scenario file) and calls finish() on it.
Mission parse_mission(const config::Config& cfg);

}  // namespace gdnav::core::gnc
namespace gdnav { namespace gnc = core::gnc; }  // the short name (docs/architecture.md, "Namespaces")

namespace gdnav::guidance {  // their names in the guidance model's API, as before
using gnc::load_mission;
using gnc::parse_mission;
}  // namespace gdnav::guidance
