#include "scenario_missions.hpp"

#include <cmath>

namespace gdnav::guidance {

namespace {

int draw_bearing_deg(rnd::Stream& s) { return s.uniform_int(-179, 180); }

// Wraps an integer bearing difference into (-180, 180].
int wrap_deg(int d) {
    while (d > 180) d -= 360;
    while (d <= -180) d += 360;
    return d;
}

int draw_bearing_apart_deg(rnd::Stream& s, int previous_deg) {
    for (;;) {
        const int b = draw_bearing_deg(s);
        if (std::abs(wrap_deg(b - previous_deg)) >= 10) return b;
    }
}

gnc::ChannelTargets initial_targets(const Scenario1Draws& d, double bearing_rad) {
    gnc::ChannelTargets t;
    t.throttle_mode = gnc::ThrottleMode::airspeed;
    t.throttle_target = d.airspeed_ini_mps;
    t.elevator_mode = gnc::ElevatorMode::pressure_altitude;
    t.elevator_target = d.pressure_altitude_ini_m;
    t.aileron_mode = gnc::AileronMode::bearing;
    t.aileron_target = bearing_rad;
    t.rudder_mode = gnc::RudderMode::sideslip;
    t.rudder_target = 0.0;
    return t;
}

}  // namespace

Scenario1Draws draw_scenario1(rnd::Stream& s, double t_gnss_loss_s) {
    Scenario1Draws d;
    const int chi_ini = draw_bearing_deg(s);
    const int chi_end = draw_bearing_apart_deg(s, chi_ini);
    d.bearing_ini_rad = math::deg2rad(chi_ini);
    d.bearing_end_rad = math::deg2rad(chi_end);
    do {
        d.airspeed_delay_s = 500.0 + 100.0 * s.normal();
    } while (d.airspeed_delay_s < 150.0);
    do {
        d.airspeed_ini_mps = 29.0 + 1.5 * s.normal();
    } while (d.airspeed_ini_mps < 24.0 || d.airspeed_ini_mps > 34.0);
    for (;;) {
        const double dv = 1.5 * s.normal();
        d.airspeed_end_mps = d.airspeed_ini_mps + dv;
        if (std::fabs(dv) >= 0.5 && d.airspeed_end_mps >= 24.0 && d.airspeed_end_mps <= 34.0) break;
    }
    do {
        d.altitude_delay_s = 500.0 + 100.0 * s.normal();
    } while (d.altitude_delay_s < 150.0 || d.airspeed_delay_s + d.altitude_delay_s > 2500.0);
    d.pressure_altitude_ini_m = 2700.0 + 200.0 * s.normal();
    for (;;) {
        const double dhp = 300.0 * s.normal();
        d.pressure_altitude_end_m = d.pressure_altitude_ini_m + dhp;
        if (std::fabs(dhp) >= 100.0) break;
    }
    do {
        d.turn_time_s = t_gnss_loss_s + 30.0 + 50.0 * s.normal();
    } while (d.turn_time_s < t_gnss_loss_s + 15.0);
    return d;
}

Scenario2Draws draw_scenario2(rnd::Stream& s, double t_gnss_loss_s) {
    Scenario2Draws d;
    d.common = draw_scenario1(s, t_gnss_loss_s);
    for (double& leg : d.leg_s) leg = s.uniform_int(10, 50);
    int previous = static_cast<int>(std::lround(math::rad2deg(d.common.bearing_end_rad)));
    for (double& chi : d.bearing_rad) {
        previous = draw_bearing_apart_deg(s, previous);
        chi = math::deg2rad(previous);
    }
    return d;
}

Mission make_scenario1_mission(const Scenario1Draws& d, double t_end_s, const ManoeuvreSettings& m) {
    MissionBuilder b("scenario1", t_end_s, initial_targets(d, d.bearing_ini_rad));
    b.hold(Trigger::time(d.turn_time_s))
        .turn(d.bearing_end_rad, m.turn_bank_rad, m.turn_lead_rad, Trigger::elapsed(d.airspeed_delay_s))
        .change_airspeed(d.airspeed_end_mps, Trigger::elapsed(d.altitude_delay_s))
        .change_altitude(d.pressure_altitude_end_m, m.climb_path_angle_rad, Trigger::time(t_end_s));
    return b.build();
}

Mission make_scenario2_mission(const Scenario2Draws& d, double t_end_s, const ManoeuvreSettings& m) {
    MissionBuilder b("scenario2", t_end_s, initial_targets(d.common, d.common.bearing_ini_rad));
    b.hold(Trigger::time(d.common.turn_time_s));
    for (std::size_t k = 0; k < 8; ++k) {
        const double chi = k == 0 ? d.common.bearing_end_rad : d.bearing_rad[k - 1];
        const Trigger then = k < 7 ? Trigger::elapsed(d.leg_s[k]) : Trigger::time(t_end_s);
        b.turn(chi, m.turn_bank_rad, m.turn_lead_rad, then);
    }
    return b.build();
}

}  // namespace gdnav::guidance
