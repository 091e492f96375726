#include "autopilot_config.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>

namespace gdnav::control {

namespace {

using config::Config;
using config::Range;

constexpr Range kGain{-1.0e4, 1.0e4};
constexpr Range kSurfaceLimit_deg{0.1, 45.0};
constexpr Range kTargetLimit_deg{0.1, 60.0};
constexpr Range kSurface_deg{-45.0, 45.0};
constexpr Range kFraction{0.0, 1.0};
constexpr Range kRampSteps{0.0, 1.0e4};

void read_kpid(const Config& c, PidGains& g) {
    g.kp = c.get_double("kp", kGain);
    g.ki = c.get_double("ki", kGain);
    g.kd = c.get_double("kd", kGain);
}

PidGains read_surface_loop(const Config& c) {
    PidGains g;
    read_kpid(c, g);
    g.u_eq = c.get_double("u_eq_deg", kSurface_deg);
    const double lim = c.get_double("limit_deg", kSurfaceLimit_deg);
    g.u_min = -lim;
    g.u_max = lim;
    return g;
}

PidGains read_outer_loop(const Config& c) {
    PidGains g;
    read_kpid(c, g);
    const double lim = c.get_double("limit_deg", kTargetLimit_deg);
    g.u_min = -lim;
    g.u_max = lim;
    return g;
}

// What a mode selects: its set-point ramp and the gains of its outer loop (none: the primary loop alone).
template <class Mode>
struct ModeEntry {
    Mode mode;
    double AutopilotConfig::RampSteps::*ramp;
    PidGains AutopilotConfig::*outer;
};
using Ramp = AutopilotConfig::RampSteps;
constexpr ModeEntry<gnc::ElevatorMode> kElevatorModes[] = {
    {gnc::ElevatorMode::pitch, &Ramp::pitch, nullptr},
    {gnc::ElevatorMode::pressure_altitude, &Ramp::pressure_altitude, &AutopilotConfig::pressure_altitude},
    {gnc::ElevatorMode::altitude, &Ramp::altitude, &AutopilotConfig::altitude},
    {gnc::ElevatorMode::air_path_angle, &Ramp::air_path_angle, &AutopilotConfig::air_path_angle},
};
constexpr ModeEntry<gnc::AileronMode> kAileronModes[] = {
    {gnc::AileronMode::bank, &Ramp::bank, nullptr},
    {gnc::AileronMode::bearing, &Ramp::bearing, &AutopilotConfig::bearing},
    {gnc::AileronMode::heading, &Ramp::heading, &AutopilotConfig::heading},
    {gnc::AileronMode::air_bank, &Ramp::air_bank, &AutopilotConfig::air_bank},
    {gnc::AileronMode::air_bearing, &Ramp::air_bearing, &AutopilotConfig::air_bearing},
};

// The entry of `m`; nullptr for a value that is no mode of the channel.
template <class Mode, std::size_t N>
const ModeEntry<Mode>* entry_of(const ModeEntry<Mode> (&modes)[N], Mode m) {
    for (const ModeEntry<Mode>& e : modes)
        if (e.mode == m) return &e;
    return nullptr;
}

template <class Mode, std::size_t N>
double ramp_of(const AutopilotConfig& a, const ModeEntry<Mode> (&modes)[N], Mode m, const char* channel) {
    const ModeEntry<Mode>* e = entry_of(modes, m);
    if (e == nullptr) throw std::invalid_argument(std::string("autopilot: invalid ") + channel + " mode");
    return a.ramp.*(e->ramp);
}

template <class Mode, std::size_t N>
const PidGains& outer_of(const AutopilotConfig& a, const ModeEntry<Mode> (&modes)[N], Mode m, const char* channel) {
    const ModeEntry<Mode>* e = entry_of(modes, m);
    if (e == nullptr || e->outer == nullptr)
        throw std::invalid_argument(std::string("autopilot: ") + channel + " mode has no outer loop");
    return a.*(e->outer);
}

}  // namespace

double AutopilotConfig::ramp_steps(gnc::ThrottleMode) const { return ramp.airspeed; }
double AutopilotConfig::ramp_steps(gnc::RudderMode) const { return ramp.sideslip; }
double AutopilotConfig::ramp_steps(gnc::ElevatorMode m) const { return ramp_of(*this, kElevatorModes, m, "elevator"); }
double AutopilotConfig::ramp_steps(gnc::AileronMode m) const { return ramp_of(*this, kAileronModes, m, "aileron"); }

const PidGains& AutopilotConfig::outer_gains(gnc::ElevatorMode m) const {
    return outer_of(*this, kElevatorModes, m, "elevator");
}
const PidGains& AutopilotConfig::outer_gains(gnc::AileronMode m) const {
    return outer_of(*this, kAileronModes, m, "aileron");
}

AutopilotConfig read_autopilot_config(const Config& cfg) {
    AutopilotConfig a;
    const Config timing = cfg.child("timing");
    a.tick_s = timing.get_double("tick_s", Range{1.0e-4, 1.0});
    a.period_ticks = static_cast<int>(timing.get_int("period_ticks", 1, 100));
    a.derivative_filter_time_s = timing.get_double("derivative_filter_time_s", Range{0.0, 100.0});

    const Config init = cfg.child("initial");
    a.initial_throttle = init.get_double("throttle", kFraction);
    a.initial_elevator_deg = init.get_double("elevator_deg", kSurface_deg);
    a.initial_aileron_deg = init.get_double("aileron_deg", kSurface_deg);
    a.initial_rudder_deg = init.get_double("rudder_deg", kSurface_deg);

    const Config prim = cfg.child("primary");
    {
        const Config t = prim.child("throttle_airspeed");
        read_kpid(t, a.throttle_airspeed);
        a.throttle_airspeed.u_eq = t.get_double("u_eq", kFraction);
        a.throttle_airspeed.u_min = t.get_double("u_min", kFraction);
        a.throttle_airspeed.u_max = t.get_double("u_max", Range{a.throttle_airspeed.u_min, 1.0});
    }
    a.elevator_pitch = read_surface_loop(prim.child("elevator_pitch"));
    a.aileron_bank = read_surface_loop(prim.child("aileron_bank"));
    a.rudder_sideslip = read_surface_loop(prim.child("rudder_sideslip"));

    const Config sec = cfg.child("secondary");
    a.pressure_altitude = read_outer_loop(sec.child("pressure_altitude"));
    a.altitude = read_outer_loop(sec.child("altitude"));
    a.air_path_angle = read_outer_loop(sec.child("air_path_angle"));
    a.bearing = read_outer_loop(sec.child("bearing"));
    a.heading = read_outer_loop(sec.child("heading"));
    a.air_bank = read_outer_loop(sec.child("air_bank"));
    a.air_bearing = read_outer_loop(sec.child("air_bearing"));

    const Config ramp = cfg.child("ramp_steps");
    a.ramp.airspeed = ramp.child("throttle").get_double("airspeed", kRampSteps);
    const Config re = ramp.child("elevator");
    a.ramp.pitch = re.get_double("pitch", kRampSteps);
    a.ramp.pressure_altitude = re.get_double("pressure_altitude", kRampSteps);
    a.ramp.altitude = re.get_double("altitude", kRampSteps);
    a.ramp.air_path_angle = re.get_double("air_path_angle", kRampSteps);
    const Config ra = ramp.child("aileron");
    a.ramp.bank = ra.get_double("bank", kRampSteps);
    a.ramp.bearing = ra.get_double("bearing", kRampSteps);
    a.ramp.heading = ra.get_double("heading", kRampSteps);
    a.ramp.air_bank = ra.get_double("air_bank", kRampSteps);
    a.ramp.air_bearing = ra.get_double("air_bearing", kRampSteps);
    a.ramp.sideslip = ramp.child("rudder").get_double("sideslip", kRampSteps);

    const Config cpl = cfg.child("bank_airspeed_coupling");
    a.coupling_gain_deg_per_mps = cpl.get_double("gain_deg_per_mps", Range{-10.0, 10.0});
    a.coupling_limit_deg = cpl.get_double("limit_deg", Range{0.0, 45.0});

    cfg.finish();
    return a;
}

}  // namespace gdnav::control
