#pragma once
// The missions of the paper's two scenarios, built from their random draws (docs/guidance-control.md, "Scenario
// missions").
//
// Draws (all from the caller's stream, in this order; N = standard normal, bearings U{-179..180} integer deg):
//   1 chi_ini;  2 chi_end, redrawn until |wrap(chi_end - chi_ini)| >= 10 deg;
//   3 dt_airspeed = 500 + 100 N s (>= 150);  4 V_ini = 29 + 1.5 N m/s in [24, 34];
//   5 dV = 1.5 N, |dV| >= 0.5 and V_ini + dV in [24, 34];  6 dt_altitude = 500 + 100 N s (>= 150, dt_airspeed +
//   dt_altitude <= 2500);  7 Hp_ini = 2700 + 200 N m;  8 dHp = 300 N m, |dHp| >= 100;
//   9 t_turn = t_gnss_loss + 30 + 50 N s (>= t_gnss_loss + 15).
// Scenario #2 makes draws 1-9 exactly as scenario #1 (same values for the same stream), then seven leg durations
// U{10..50} s, then bearings chi_2..chi_8, each redrawn until |wrap(chi_k - chi_{k-1})| >= 10 deg.
//
// Missions (turn: bank +-10 deg ending 5 deg before the target; altitude change: air-path angle +-2 deg):
//   #1 (6 ops, 3800 s): hold(V_ini, Hp_ini, chi_ini) until t >= t_turn | turn to chi_end | hold chi_end for
//      dt_airspeed | airspeed V_end for dt_altitude | climb/descend to Hp_end | hold Hp_end until t >= t_end.
//   #2 (17 ops, 500 s): hold(V_ini, Hp_ini, chi_0) until t >= t_turn | for k = 1..8: turn to chi_k, hold chi_k for
//      leg k+1 (the last hold lasts until t >= t_end). V_ini and Hp_ini are held throughout.
// Rudder: sideslip 0 in every operation.
#include <array>

#include "math/rotation.hpp"
#include "gnc/mission.hpp"
#include "random/stream.hpp"

namespace gdnav::guidance {

struct Scenario1Draws {
    double bearing_ini_rad{0.0};       // chi_ini (an integer number of degrees)
    double bearing_end_rad{0.0};       // chi_end (an integer number of degrees)
    double airspeed_delay_s{0.0};      // dt from the end of the turn to the airspeed change
    double airspeed_ini_mps{0.0};      // V_ini
    double airspeed_end_mps{0.0};      // V_end = V_ini + dV
    double altitude_delay_s{0.0};      // dt from the airspeed change to the altitude change
    double pressure_altitude_ini_m{0.0};
    double pressure_altitude_end_m{0.0};
    double turn_time_s{0.0};           // t_turn: absolute time at which the first turn starts
};

struct Scenario2Draws {
    Scenario1Draws common;             // draws 1-9; chi_0 = common.bearing_ini_rad, chi_1 = common.bearing_end_rad
    std::array<double, 7> leg_s{};     // straight legs after turns 1..7 (integer seconds)
    std::array<double, 7> bearing_rad{};  // chi_2..chi_8 (integer degrees)
};

// The manoeuvre conventions of the paper.
struct ManoeuvreSettings {
    double turn_bank_rad{math::deg2rad(10.0)};
    double turn_lead_rad{math::deg2rad(5.0)};
    double climb_path_angle_rad{math::deg2rad(2.0)};
};

Scenario1Draws draw_scenario1(rnd::Stream& stream, double t_gnss_loss_s = 100.0);
Scenario2Draws draw_scenario2(rnd::Stream& stream, double t_gnss_loss_s = 100.0);

Mission make_scenario1_mission(const Scenario1Draws& d, double t_end_s = 3800.0, const ManoeuvreSettings& m = {});
Mission make_scenario2_mission(const Scenario2Draws& d, double t_end_s = 500.0, const ManoeuvreSettings& m = {});

}  // namespace gdnav::guidance
