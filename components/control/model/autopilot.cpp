#include "autopilot.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace gdnav::control {

namespace {
double deg(double rad) { return math::rad2deg(rad); }
// Bearing-type error in degrees, wrapped to (-180, 180].
double bearing_error_deg(double target_rad, double measured_rad) { return deg(math::wrap_pi(target_rad - measured_rad)); }

// A channel entering a new mode: its outer loop takes that mode's gains (where the mode has an outer loop) and
// starts from rest, so no integral or derivative state carries over from another mode.
template <class Mode>
void enter_mode(std::optional<Mode>& current, Mode next, DiscretePid& outer, const AutopilotConfig& cfg) {
    if (current == next) return;
    current = next;
    if (gnc::has_outer_loop(next)) outer.set_gains(cfg.outer_gains(next));
    outer.reset();
}
}  // namespace

void Autopilot::configure(const config::Config& cfg) { configure(read_autopilot_config(cfg)); }

void Autopilot::configure(const AutopilotConfig& cfg) {
    if (cfg.period_ticks < 1 || !(cfg.tick_s > 0.0) || !(cfg.derivative_filter_time_s >= 0.0))
        throw std::invalid_argument("autopilot: period_ticks >= 1, tick_s > 0 and derivative_filter_time_s >= 0");
    cfg_ = cfg;
    const double dt = cfg_.control_period_s();
    const double tf = cfg_.derivative_filter_time_s;
    thr_ = DiscretePid(cfg_.throttle_airspeed, tf, dt);
    elv_ = DiscretePid(cfg_.elevator_pitch, tf, dt);
    ail_ = DiscretePid(cfg_.aileron_bank, tf, dt);
    rud_ = DiscretePid(cfg_.rudder_sideslip, tf, dt);
    elv_outer_ = DiscretePid(cfg_.pressure_altitude, tf, dt);  // gains replaced when a mode is entered
    ail_outer_ = DiscretePid(cfg_.bearing, tf, dt);
    configured_ = true;
    initialized_ = false;
}

void Autopilot::initialize(const ControlEstimates& first_estimate) {
    if (!configured_) throw std::logic_error("autopilot: initialize() before configure()");
    const LoopMeasurements m = measure(first_estimate);
    for (DiscretePid* pid : {&thr_, &elv_, &ail_, &rud_, &elv_outer_, &ail_outer_}) pid->reset();
    thr_ramp_.reset(m.airspeed_mps);
    elv_ramp_.reset(deg(m.pitch_rad));
    ail_ramp_.reset(deg(m.bank_rad));
    rud_ramp_.reset(deg(m.sideslip_rad));
    elv_mode_.reset();
    ail_mode_.reset();
    primary_ = {m.airspeed_mps, m.pitch_rad, m.bank_rad, m.sideslip_rad};
    out_ = {cfg_.initial_throttle, math::deg2rad(cfg_.initial_elevator_deg), math::deg2rad(cfg_.initial_aileron_deg),
            math::deg2rad(cfg_.initial_rudder_deg)};
    initialized_ = true;
}

double Autopilot::elevator_command_deg(const gnc::ChannelTargets& t, const LoopMeasurements& m) {
    using M = gnc::ElevatorMode;
    enter_mode(elv_mode_, t.elevator_mode, elv_outer_, cfg_);
    switch (t.elevator_mode) {
        case M::pitch: return deg(t.elevator_target);
        case M::pressure_altitude: return elv_outer_.step(t.elevator_target - m.pressure_altitude_m);
        case M::altitude: return elv_outer_.step(t.elevator_target - m.altitude_m);
        case M::air_path_angle: return elv_outer_.step(deg(t.elevator_target - m.air_path_angle_rad));
    }
    throw std::invalid_argument("autopilot: invalid elevator mode");
}

double Autopilot::aileron_command_deg(const gnc::ChannelTargets& t, const LoopMeasurements& m) {
    using M = gnc::AileronMode;
    enter_mode(ail_mode_, t.aileron_mode, ail_outer_, cfg_);
    switch (t.aileron_mode) {
        case M::bank: return deg(t.aileron_target);
        case M::bearing: return ail_outer_.step(bearing_error_deg(t.aileron_target, m.ground_bearing_rad));
        case M::heading: return ail_outer_.step(bearing_error_deg(t.aileron_target, m.heading_rad));
        case M::air_bank: return ail_outer_.step(deg(t.aileron_target - m.air_bank_rad));
        case M::air_bearing: return ail_outer_.step(bearing_error_deg(t.aileron_target, m.air_bearing_rad));
    }
    throw std::invalid_argument("autopilot: invalid aileron mode");
}

ControlOutput Autopilot::step(std::uint64_t k, const guidance::GuidanceOutput& targets, const ControlEstimates& est) {
    if (!initialized_) throw std::logic_error("autopilot: step() before initialize()");
    const auto period = static_cast<std::uint64_t>(cfg_.period_ticks);
    if (k == 0 || k % period != 0) return out_;  // hold the last command between actions

    const gnc::ChannelTargets& t = targets.targets;
    const LoopMeasurements m = measure(est);

    // Throttle <- airspeed.
    thr_ramp_.set_steps(cfg_.ramp_steps(t.throttle_mode));
    const double v_t = thr_ramp_.step(t.throttle_target);
    const double throttle = thr_.step(v_t - m.airspeed_mps);

    // Elevator <- pitch (target from the pitch mode or an outer loop).
    elv_ramp_.set_steps(cfg_.ramp_steps(t.elevator_mode));
    const double theta_t_deg = elv_ramp_.step(elevator_command_deg(t, m));
    const double elevator_deg = elv_.step(theta_t_deg - deg(m.pitch_rad));

    // Ailerons <- bank (target from the bank mode or an outer loop); airspeed coupling in bank mode only.
    ail_ramp_.set_steps(cfg_.ramp_steps(t.aileron_mode));
    const double xi_t_deg = ail_ramp_.step(aileron_command_deg(t, m));
    double aileron_deg = ail_.step_unsaturated(xi_t_deg - deg(m.bank_rad));
    if (t.aileron_mode == gnc::AileronMode::bank)
        aileron_deg += std::clamp(cfg_.coupling_gain_deg_per_mps * (v_t - m.airspeed_mps), -cfg_.coupling_limit_deg,
                                  cfg_.coupling_limit_deg);
    aileron_deg = ail_.saturate(aileron_deg);

    // Rudder <- sideslip.
    rud_ramp_.set_steps(cfg_.ramp_steps(t.rudder_mode));
    const double beta_t_deg = rud_ramp_.step(deg(t.rudder_target));
    const double rudder_deg = rud_.step(beta_t_deg - deg(m.sideslip_rad));

    primary_ = {v_t, math::deg2rad(theta_t_deg), math::deg2rad(xi_t_deg), math::deg2rad(beta_t_deg)};
    out_ = {throttle, math::deg2rad(elevator_deg), math::deg2rad(aileron_deg), math::deg2rad(rudder_deg)};
    return out_;
}

}  // namespace gdnav::control
