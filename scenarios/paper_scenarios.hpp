#pragma once
// The paper's two Monte Carlo scenarios as scenario generators (docs/montecarlo.md, "Scenarios #1 and #2").
//
//   generator: {name: paper_scenario1}          # or paper_scenario2; options below
//   run: {seed: 1, t0_s: -50, duration_s: 3850, ...}
//   components: {flight_physics: {type: flight_physics, ...}, guidance: {type: guidance}, ...}
//
// Run `run_index` of master seed `seed` draws, each part from its own stream
//   Stream::derive(seed, run_index, "scenario/mission")  guidance::draw_scenario1 / draw_scenario2
//   Stream::derive(seed, run_index, "scenario/wind")     physics::draw_wind_scenario
//   Stream::derive(seed, run_index, "scenario/offsets")  atm::draw_offsets_scenario
//   Stream::derive(seed, run_index, "scenario/earth")    earth::draw_earth_truth
// (so, as in the reference, both scenarios share chi_0, chi_1, V_ini, Hp_ini, t_turn, the initial wind, dT_ini, dp_ini
// and the Earth deviations for one (seed, run)), and writes them as explicit values into the component sections:
//   flight_physics  initial: {tas_mps, Hp_m, bearing_deg} (the mission's first operation), wind, offsets, earth_truth
//   guidance        mission: inline mapping (mission_yaml.hpp format: hold, turn, airspeed_change, altitude_change)
//   sensors_gnss    loss_time_s: t_GNSS
//   nav_recorder    t_gnss_s: t_GNSS
// Sections are found by component TYPE. Anything the scenario file already sets is kept (the file overrides the
// draw, key by key: e.g. `wind: {speed_ini_mps: 0}` keeps the drawn times and bearings); when the file gives the
// guidance `mission`, no mission and no initial tas/Hp/bearing are written (give them in the file).
//
// Generator options:
//   t_gnss_s: 100        GNSS loss time (default 100 s)
//   t_end_s: 3800        mission end (default 3800 s for #1, 500 s for #2)
//   fixed:               draws to fix instead of drawing (the others are still drawn, from the same streams):
//     bearing_ini_deg, bearing_end_deg, airspeed_ini_mps, airspeed_end_mps, airspeed_delay_s, altitude_delay_s,
//     Hp_ini_m, Hp_end_m, turn_time_s; scenario #2 also legs_s: [7 values], bearings_deg: [7 values]
//   calibration:         a GNSS-aided calibration pattern flown before the file's t0 (calibration_pattern.hpp): the
//                        run starts earlier, the pattern's operations go before the drawn mission; it draws nothing,
//                        so every draw above is the same with and without it
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "atmosphere/offsets_ramp.hpp"
#include "calibration_pattern.hpp"
#include "config/config.hpp"
#include "earth/gravity.hpp"
#include "flight_physics/model/wind_ramp.hpp"
#include "guidance/model/scenario_missions.hpp"

namespace gdnav::scenario {

struct PaperDraws {
    int scenario{1};  // 1 or 2
    std::uint64_t seed{0};
    std::uint64_t run_index{0};
    double t_gnss_s{100.0};
    double t_end_s{3800.0};
    guidance::Scenario2Draws mission;  // scenario #1 uses mission.common only
    physics::WindRampParams wind;
    atm::OffsetsRampParams offsets;
    earth::EarthTruthParams earth;
    std::optional<CalibrationPattern> calibration;  // generator option, not a draw
};

// Draws scenario `scenario` (1 or 2) for (seed, run_index). `options` is the generator section (may be null).
PaperDraws draw_paper_scenario(int scenario, std::uint64_t seed, std::uint64_t run_index,
                               const config::Config* options);
// The mission flown (guidance::make_scenario1_mission / make_scenario2_mission of the draws).
guidance::Mission paper_mission(const PaperDraws& d);
// The mission as an inline YAML mapping (config/missions format), with the calibration pattern's operations first
// when the option is on.
YAML::Node paper_mission_yaml(const PaperDraws& d);

struct GeneratedScenario {
    YAML::Node doc;                 // complete run config (without the `generator` key)
    PaperDraws draws;
    std::vector<std::string> kept;  // paths the scenario file fixed (drawn value not used)
};
GeneratedScenario generate_paper_scenario(int scenario, const YAML::Node& doc, std::uint64_t seed,
                                          std::uint64_t run_index, const std::string& origin);

// Human-readable account of the draws (gdnav scenario).
std::string describe(const PaperDraws& d);

// Registers paper_scenario1 and paper_scenario2 with framework::register_scenario_generator.
void register_paper_scenarios();

}  // namespace gdnav::scenario
