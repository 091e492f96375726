#include "guidance_component.hpp"

#include <optional>

#include "gnc/modes.hpp"
#include "gnc_inputs/estimate_inputs.hpp"
#include "guidance/model/guidance.hpp"
#include "guidance/model/mission_yaml.hpp"
#include "framework/run_config.hpp"

namespace gdnav::guidance {

namespace {

class GuidanceComponent final : public runtime::Component {
public:
    using Component::Component;
    void configure(const config::Config& cfg, const runtime::RunInfo&, rnd::Stream&) override {
        Mission m = cfg.node()["mission"].IsMap() ? parse_mission(cfg.child("mission"))
                                                  : load_mission(cfg.get_file("mission", runtime::config_dir()));
        try {
            guidance_.emplace(m);
        } catch (const std::invalid_argument& e) {
            cfg.fail("mission", e.what());
        }
    }
    void step(const runtime::StepContext& ctx) override {
        auto& o = out_.value();
        if (!est_.available()) {  // estimates lost: hold the last targets
            return;
        }
        const GuidanceOutput g = guidance_->step(ctx.t_s, est_.nav_state());
        o.operation(g.operation);
        o.throttle_mode(gnc::to_octet(g.targets.throttle_mode));
        o.throttle_target(g.targets.throttle_target);
        o.elevator_mode(gnc::to_octet(g.targets.elevator_mode));
        o.elevator_target(g.targets.elevator_target);
        o.aileron_mode(gnc::to_octet(g.targets.aileron_mode));
        o.aileron_target(g.targets.aileron_target);
        o.rudder_mode(gnc::to_octet(g.targets.rudder_mode));
        o.rudder_target(g.targets.rudder_target);
        o.finished(g.finished);
        if (g.operation != last_op_) {
            publish_status("operation " + std::to_string(g.operation));
            last_op_ = g.operation;
        }
    }

private:
    EstimateInputs est_{*this};
    runtime::Output<msg::GuidanceTargets> out_{*this, topics::kGuidance};
    std::optional<Guidance> guidance_;
    std::uint32_t last_op_{0};
};

}  // namespace

void register_guidance_component(runtime::ComponentRegistry& reg) {
    reg.add("guidance", "mission operations and triggers: estimates -> GuidanceTargets",
            runtime::make_factory<GuidanceComponent>());
}

}  // namespace gdnav::guidance
