#pragma once
// Autopilot: the four-channel PID control law of the reference (docs/guidance-control.md, "Control"), closed on the
// navigation estimates.
//
// Inputs  (every 10-ms step k): GuidanceOutput (modes + SI targets), ControlEstimates (navigation output)
// Output  (every step):         ControlOutput throttle in [0, 1]; elevator, aileron, rudder deflections [rad]
//
// Rate: the law acts when k is a multiple of period_ticks (2: 50 Hz) and k > 0; k = 0 is the initial epoch with
// the initial commands (0.3, 0, 0, 0); between actions the last command is held (no actuator dynamics).
//
// Per action, in degrees for the angles (gains are per degree; surfaces are converted to radians at the output):
//   throttle  V_t = ramp_V(V_target);                  dT = PID_V(V_t - V)
//   elevator  theta_c = theta_target                   (pitch mode)
//                     = clamp(PID_outer(e_outer))      (Hp: e = Hp_t - Hp; h: e = h_t - h; gamma_TAS: e = g_t - g)
//             theta_t = ramp_theta(theta_c);           dE = PID_theta(theta_t - theta)
//   aileron   xi_c = xi_target                         (bank mode)
//                  = clamp(PID_outer(e_outer))         (chi, psi, chi_TAS: e = wrap(target - measured); mu_TAS)
//             xi_t = ramp_xi(xi_c);                    dA = PID_xi(xi_t - xi) [+ coupling in bank mode], clamped
//             coupling = clamp(g_c (V_t - V), +-L_c)   (reference: 0.1 deg per m/s added twice = 0.2, see docs)
//   rudder    beta_t = ramp_beta(beta_target);         dR = PID_beta(beta_t - beta)
// The ramp of each channel uses the N of the channel's current mode. On a change of elevator or aileron mode the
// channel's outer-loop state (integral, filtered error) is reset to zero; primary states and ramps carry over.
// initialize() starts the ramps at the estimated V, theta, xi, beta and zeroes every PID state.
//
// Deviation from the reference: its bearing-type errors are NaN beyond +-90 deg (which would poison the PID for
// ever); here the wrapped error in (-180, 180] is used, so a large bearing change saturates the bank target.
#include <cstdint>
#include <optional>

#include "autopilot_config.hpp"
#include "gnc/guidance_output.hpp"
#include "measurements.hpp"
#include "pid.hpp"

namespace gdnav::control {

struct ControlOutput {
    double throttle{0.0};      // [0, 1]
    double elevator_rad{0.0};
    double aileron_rad{0.0};
    double rudder_rad{0.0};
};

// Ramped set points of the primary loops at the last action (SI).
struct PrimaryTargets {
    double airspeed_mps{0.0};
    double pitch_rad{0.0};
    double bank_rad{0.0};
    double sideslip_rad{0.0};
};

class Autopilot {
public:
    Autopilot() = default;
    explicit Autopilot(const AutopilotConfig& cfg) { configure(cfg); }

    // Reads config/control/mugin_autopilot.yaml-style parameters (ConfigError on any bad or unknown key).
    void configure(const config::Config& cfg);
    void configure(const AutopilotConfig& cfg);
    // Must be called once after configure() and before the first step(), with the first navigation estimate.
    void initialize(const ControlEstimates& first_estimate);

    ControlOutput step(std::uint64_t k, const guidance::GuidanceOutput& targets, const ControlEstimates& est);

    [[nodiscard]] const AutopilotConfig& config() const { return cfg_; }
    [[nodiscard]] const PrimaryTargets& primary_targets() const { return primary_; }
    [[nodiscard]] const ControlOutput& last_output() const { return out_; }

private:
    double elevator_command_deg(const gnc::ChannelTargets& t, const LoopMeasurements& m);
    double aileron_command_deg(const gnc::ChannelTargets& t, const LoopMeasurements& m);

    AutopilotConfig cfg_{};
    bool configured_{false};
    bool initialized_{false};

    DiscretePid thr_, elv_, ail_, rud_;    // primary loops
    DiscretePid elv_outer_, ail_outer_;    // outer loop of each channel (gains follow the mode)
    RampFilter thr_ramp_, elv_ramp_, ail_ramp_, rud_ramp_;
    std::optional<gnc::ElevatorMode> elv_mode_;
    std::optional<gnc::AileronMode> ail_mode_;

    PrimaryTargets primary_{};
    ControlOutput out_{};
};

}  // namespace gdnav::control
