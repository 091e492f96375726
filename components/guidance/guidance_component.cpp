#include "guidance_component.hpp"

#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "gnc/modes.hpp"
#include "gnc_inputs/estimate_inputs.hpp"
#include "guidance/model/guidance.hpp"
#include "gnc/mission_yaml.hpp"
#include "guidance/model/until_aligned.hpp"
#include "msgs/alignment_messages.hpp"
#include "framework/run_config.hpp"

namespace gdnav::guidance {

namespace {

class GuidanceComponent final : public framework::Component {
public:
    using Component::Component;
    void configure(const config::Config& cfg, const framework::RunInfo&, rnd::Stream&) override {
        Mission m = cfg.node()["mission"].IsMap() ? parse_mission(cfg.child("mission"))
                                                  : load_mission(cfg.get_file("mission", framework::config_dir()));
        try {
            guidance_.emplace(m);
        } catch (const std::invalid_argument& e) {
            cfg.fail("mission", e.what());
        }
        // Needs nav_pos's `alignment_check` (gdnav/NavAlignment); a run without that producer fails at start.
        if (cfg.get_bool("until_aligned", false))
            aligned_ = std::make_unique<framework::Input<msg::NavAlignment>>(*this, topics::kAlignment);
    }
    void step(const framework::StepContext& ctx) override {
        auto& o = out_.value();
        if (!est_.available()) {  // estimates lost: hold the last targets
            return;
        }
        GuidanceOutput g = guidance_->step(ctx.t_s, est_.nav_state());
        if (aligned_) fly_safely_until_aligned(g, ctx.t_s);
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
    // The elevator flies level through the air until the navigation says it is aligned (until_aligned.hpp); a
    // missing NavAlignment sample counts as not aligned.
    void fly_safely_until_aligned(GuidanceOutput& g, double t_s) {
        if (!cleared_ && aligned_->available() && aligned_->get().aligned()) {
            cleared_ = true;
            publish_status(fmt::format("navigation aligned: flying the mission's altitude targets from t = {:.2f} s",
                                       t_s));
        }
        if (cleared_) return;
        if (!announced_ && needs_altitude(g.targets.elevator_mode)) {
            announced_ = true;
            publish_status("navigation not aligned: altitude targets flown as air_path_angle 0 until it is");
        }
        g.targets = until_aligned(g.targets);
    }

    EstimateInputs est_{*this};
    std::unique_ptr<framework::Input<msg::NavAlignment>> aligned_;
    bool cleared_{false};
    bool announced_{false};
    framework::Output<msg::GuidanceTargets> out_{*this, topics::kGuidance};
    std::optional<Guidance> guidance_;
    std::uint32_t last_op_{0};
};

}  // namespace

void register_guidance_component(framework::ComponentRegistry& reg) {
    reg.add("guidance", "mission operations and triggers: estimates -> GuidanceTargets",
            framework::make_factory<GuidanceComponent>());
}

}  // namespace gdnav::guidance
