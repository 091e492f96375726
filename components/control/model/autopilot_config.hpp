#pragma once
// Autopilot parameters (config/control/mugin_autopilot.yaml). Gains are per control step and, for the angle
// loops, per degree: the autopilot runs its PIDs in degrees (as the reference gains were tuned) and converts the
// surface deflections to radians at its output.
//
//   timing.tick_s, timing.period_ticks        control period dt_c = period_ticks * tick_s (0.02 s: 50 Hz)
//   timing.derivative_filter_time_s           T_f of every PID's error low-pass (0.32 s = 16 dt_c)
//   initial.{throttle, elevator_deg, ...}     commands before the first control step (0.3, 0, 0, 0)
//   primary.<loop>                            throttle<-airspeed [1 per m/s], elevator<-pitch, aileron<-bank,
//                                             rudder<-sideslip [deg per deg]: kp, ki, kd, u_eq, limits
//   secondary.<mode>                          outer loops producing the pitch / bank target [deg per m or deg]
//   ramp_steps.<channel>.<mode>               set-point ramp N of each mode (time constant ~ N dt_c)
//   bank_airspeed_coupling                    aileron term clamp(gain (V_target - V), +-limit) [deg], bank mode only
#include "config/config.hpp"
#include "gnc/modes.hpp"
#include "pid.hpp"

namespace gdnav::control {

// Every value comes from the configuration file; a default-constructed AutopilotConfig is all zero gains.
struct AutopilotConfig {
    double tick_s{0.01};
    int period_ticks{1};
    double derivative_filter_time_s{0.0};

    double initial_throttle{0.0};
    double initial_elevator_deg{0.0};
    double initial_aileron_deg{0.0};
    double initial_rudder_deg{0.0};

    // Primary loops (u in throttle fraction or degrees).
    PidGains throttle_airspeed;
    PidGains elevator_pitch;
    PidGains aileron_bank;
    PidGains rudder_sideslip;

    // Secondary loops (u = pitch or bank target in degrees; u_eq = 0, symmetric limits).
    PidGains pressure_altitude;
    PidGains altitude;
    PidGains air_path_angle;
    PidGains bearing;
    PidGains heading;
    PidGains air_bank;
    PidGains air_bearing;

    struct RampSteps {
        double airspeed{0.0};
        double pitch{0.0};
        double pressure_altitude{0.0};
        double altitude{0.0};
        double air_path_angle{0.0};
        double bank{0.0};
        double bearing{0.0};
        double heading{0.0};
        double air_bank{0.0};
        double air_bearing{0.0};
        double sideslip{0.0};
    } ramp;

    double coupling_gain_deg_per_mps{0.0};
    double coupling_limit_deg{0.0};

    [[nodiscard]] double control_period_s() const { return tick_s * period_ticks; }
    [[nodiscard]] double ramp_steps(gnc::ThrottleMode m) const;
    [[nodiscard]] double ramp_steps(gnc::ElevatorMode m) const;
    [[nodiscard]] double ramp_steps(gnc::AileronMode m) const;
    [[nodiscard]] double ramp_steps(gnc::RudderMode m) const;
    // Gains of the outer loop serving a mode (mode must have an outer loop).
    [[nodiscard]] const PidGains& outer_gains(gnc::ElevatorMode m) const;
    [[nodiscard]] const PidGains& outer_gains(gnc::AileronMode m) const;
};

// Reads and validates every value (ConfigError naming file and key) and rejects unknown keys (finish()).
AutopilotConfig read_autopilot_config(const config::Config& cfg);

}  // namespace gdnav::control
