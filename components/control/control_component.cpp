#include "control_component.hpp"

#include "control/model/autopilot.hpp"
#include "gnc/modes.hpp"
#include "gnc_inputs/estimate_inputs.hpp"
#include "framework/run_config.hpp"

namespace gdnav::control {

namespace {

class ControlComponent final : public framework::Component {
public:
    using Component::Component;
    void configure(const config::Config& cfg, const framework::RunInfo&, rnd::Stream&) override {
        const auto file = cfg.get_file("autopilot", "control/mugin_autopilot.yaml", framework::config_dir());
        autopilot_.configure(config::Config::load(file));
    }
    void step(const framework::StepContext& ctx) override {
        if (!est_.available() || !targets_.available()) return;  // hold the last command
        const control::ControlEstimates e = est_.control_estimates();
        if (!initialized_) {
            autopilot_.initialize(e);
            initialized_ = true;
        }
        const auto& t = targets_.get();
        guidance::GuidanceOutput g;
        g.operation = t.operation();
        g.finished = t.finished();
        g.targets.throttle_mode = gnc::mode_from_octet<gnc::ThrottleMode>(t.throttle_mode()).value_or(gnc::ThrottleMode::airspeed);
        g.targets.throttle_target = t.throttle_target();
        g.targets.elevator_mode = gnc::mode_from_octet<gnc::ElevatorMode>(t.elevator_mode()).value_or(gnc::ElevatorMode::pitch);
        g.targets.elevator_target = t.elevator_target();
        g.targets.aileron_mode = gnc::mode_from_octet<gnc::AileronMode>(t.aileron_mode()).value_or(gnc::AileronMode::bank);
        g.targets.aileron_target = t.aileron_target();
        g.targets.rudder_mode = gnc::mode_from_octet<gnc::RudderMode>(t.rudder_mode()).value_or(gnc::RudderMode::sideslip);
        g.targets.rudder_target = t.rudder_target();
        const ControlOutput u = autopilot_.step(ctx.k, g, e);
        auto& o = out_.value();
        o.throttle(u.throttle);
        o.elevator_rad(u.elevator_rad);
        o.aileron_rad(u.aileron_rad);
        o.rudder_rad(u.rudder_rad);
    }

private:
    guidance::EstimateInputs est_{*this};
    framework::Input<msg::GuidanceTargets> targets_{*this, topics::kGuidance};
    framework::Output<msg::ControlCommands> out_{*this, topics::kControls};
    Autopilot autopilot_;
    bool initialized_{false};
};

}  // namespace

void register_control_component(framework::ComponentRegistry& reg) {
    reg.add("control", "autopilot PID loops at 50 Hz: targets + estimates -> ControlCommands",
            framework::make_factory<ControlComponent>());
}

}  // namespace gdnav::control
