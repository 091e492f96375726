#pragma once
// flight_physics: ControlCommands(k-1) -> Truth(k). Integrates the Mugin's equations of motion (Heun, 500 Hz, five
// sub-steps per 10-ms tick) with wind, Dryden turbulence (generated from the component's stream), INSA offsets and
// the per-run true gravity and magnetic field; publishes the full truth at the end of each tick. Step 0 publishes
// the trimmed initial state.
//
// Config section:
//   aircraft: aircraft/mugin.yaml                 # relative to config/
//   magnetic_model: earth/magnetic_wisconsin.yaml
//   initial: {lat_deg: 45, lon_deg: -90, mass_kg: 19.5, tas_mps: 29, Hp_m: 2700, bearing_deg: -72}
//            # or `mission: missions/x.yaml` instead of tas/Hp/bearing: the mission's first operation's values
//   turbulence: {factor: 0.5, intensity_mps: 0.5858 | probability_of_exceedance: 0.01, scale_length_m: 533.4,
//                noise_time_constant_s: 0.05}
//   wind: {t_ini_s, t_end_s, speed_ini_mps, bearing_ini_deg, speed_end_mps, bearing_end_deg}       (optional)
//   offsets: {dT_ini_K, dT_end_K, t_ini_dT_s, t_end_dT_s, dp_ini_Pa, dp_end_Pa, t_ini_dp_s, t_end_dp_s} (optional)
//   earth_truth: {dg_mps2, tilt_deg, tilt_axis_bearing_deg, mag_dev_n_nT: [N, E, D]}                 (optional)
//   draw: none | scenario1 | scenario2   # draw whatever of wind/offsets/earth_truth is not given from this
//                                        # component's stream with the scenario's distributions (default none)
#include "framework/registry.hpp"

namespace gdnav::physics {
void register_flight_physics(framework::ComponentRegistry& reg);
}
