// Human-readable account of a paper scenario's draws (gdnav scenario).
#include <cmath>
#include <cstdio>
#include <string>

#include "paper_scenarios.hpp"

namespace gdnav::scenario {

namespace {

double deg(double rad) { return math::rad2deg(rad); }

const char* side(double from_rad, double to_rad) { return math::wrap_pi(to_rad - from_rad) > 0.0 ? "right" : "left"; }

}  // namespace

std::string describe(const PaperDraws& d) {
    const auto& c = d.mission.common;
    std::string s;
    char b[512];
    std::snprintf(b, sizeof(b), "paper scenario #%d, seed %llu, run %llu: t_GNSS = %g s, t_end = %g s\n", d.scenario,
                  static_cast<unsigned long long>(d.seed), static_cast<unsigned long long>(d.run_index), d.t_gnss_s,
                  d.t_end_s);
    s += b;
    if (d.calibration) s += describe_calibration(*d.calibration, c.airspeed_ini_mps);
    s += "mission (streams scenario/mission):\n";
    std::snprintf(b, sizeof(b), "  initial     V_ini %.3f m/s, Hp_ini %.1f m, chi_0 %+.0f deg\n", c.airspeed_ini_mps,
                  c.pressure_altitude_ini_m, deg(c.bearing_ini_rad));
    s += b;
    std::snprintf(b, sizeof(b), "  turn 1      at t = %.2f s: chi %+.0f -> %+.0f deg (%s, bank 10 deg)\n", c.turn_time_s,
                  deg(c.bearing_ini_rad), deg(c.bearing_end_rad), side(c.bearing_ini_rad, c.bearing_end_rad));
    s += b;
    if (d.scenario == 1) {
        std::snprintf(b, sizeof(b), "  airspeed    %.2f s after the turn: %.3f -> %.3f m/s\n", c.airspeed_delay_s,
                      c.airspeed_ini_mps, c.airspeed_end_mps);
        s += b;
        std::snprintf(b, sizeof(b), "  altitude    %.2f s after the airspeed change: Hp %.1f -> %.1f m (%s at 2 deg)\n",
                      c.altitude_delay_s, c.pressure_altitude_ini_m, c.pressure_altitude_end_m,
                      c.pressure_altitude_end_m > c.pressure_altitude_ini_m ? "climb" : "descent");
        s += b;
    } else {
        double prev = c.bearing_end_rad;
        for (std::size_t k = 0; k < 7; ++k) {
            std::snprintf(b, sizeof(b), "  turn %zu      after a %2.0f s leg: chi %+.0f -> %+.0f deg (%s)\n", k + 2,
                          d.mission.leg_s[k], deg(prev), deg(d.mission.bearing_rad[k]),
                          side(prev, d.mission.bearing_rad[k]));
            s += b;
            prev = d.mission.bearing_rad[k];
        }
        s += "  (V_ini and Hp_ini held throughout; the last hold lasts until t_end)\n";
    }
    const auto& w = d.wind;
    s += "wind (stream scenario/wind; bearing = direction the air moves towards):\n";
    if (std::fabs(w.speed_end_mps - w.speed_ini_mps) < 1e-9 && std::fabs(math::wrap_pi(w.bearing_end_rad - w.bearing_ini_rad)) < 1e-9)
        std::snprintf(b, sizeof(b), "  constant %.2f m/s towards %+.1f deg\n", w.speed_ini_mps, deg(w.bearing_ini_rad));
    else
        std::snprintf(b, sizeof(b),
                      "  %.2f m/s towards %+.1f deg until t = %.1f s, ramp to %.2f m/s towards %+.1f deg at t = %.1f s\n",
                      w.speed_ini_mps, deg(w.bearing_ini_rad), w.t_ini_s, w.speed_end_mps, deg(w.bearing_end_rad),
                      w.t_end_s);
    s += b;
    const auto& o = d.offsets;
    s += "atmosphere offsets (stream scenario/offsets):\n";
    auto ramp = [&](const char* what, const char* unit, const char* f, double v0, double v1, double t0, double t1) {
        char fmt[128];
        if (v0 == v1) {
            std::snprintf(fmt, sizeof(fmt), "  %%s constant %s %%s\n", f);
            std::snprintf(b, sizeof(b), fmt, what, v0, unit);
        } else {
            std::snprintf(fmt, sizeof(fmt), "  %%s %s %%s -> %s %%s between t = %%.1f and %%.1f s\n", f, f);
            std::snprintf(b, sizeof(b), fmt, what, v0, unit, v1, unit, t0, t1);
        }
        s += b;
    };
    ramp("dT", "K", "%+.3f", o.dT_ini_K, o.dT_end_K, o.t_ini_dT_s, o.t_end_dT_s);
    ramp("dp", "Pa", "%+.1f", o.dp_ini_Pa, o.dp_end_Pa, o.t_ini_dp_s, o.t_end_dp_s);
    const auto& e = d.earth;
    s += "Earth truth (stream scenario/earth):\n";
    std::snprintf(b, sizeof(b), "  gravity: |g| %+.3e m/s^2, tilt %.5f deg about the horizontal axis of bearing %+.0f deg\n",
                  e.dg_mps2, deg(e.tilt_rad), deg(e.tilt_axis_bearing_rad));
    s += b;
    std::snprintf(b, sizeof(b), "  magnetic deviation (N, E, D): %+.1f, %+.1f, %+.1f nT\n", e.mag_dev_n_nT.x(),
                  e.mag_dev_n_nT.y(), e.mag_dev_n_nT.z());
    s += b;
    return s;
}

}  // namespace gdnav::scenario
