// nav_air: the air data filter (model/air_data_filter.hpp) on the air data and atmospheric samples.
#include <string>

#include <spdlog/fmt/fmt.h>

#include "model/air_data_filter.hpp"
#include "msgs/messages.hpp"
#include "nav_convert.hpp"
#include "nav_files.hpp"

namespace gdnav::nav {

namespace {

class NavAir final : public FilterComponent<AirDataFilter> {
public:
    using FilterComponent::FilterComponent;
    void configure(const config::Config& cfg, const framework::RunInfo&, rnd::Stream& stream) override {
        const NavFiles files = load_nav_files(cfg, false);
        filter_.configure(files.tuning.child("air"), stream);
    }
    void step(const framework::StepContext& ctx) override {
        if (!air_.available() || !atm_.available()) return;  // a lost sensor: hold the last estimate
        const AirSample a = from_msg(air_.get());
        const AtmSample p = from_msg(atm_.get());
        if (!filter_.initialized() && (!checks::air_ok(a) || !checks::atm_ok(p))) {
            reject_before_init();  // wait for a good pair
            return;
        }
        const AirDataEstimate e =
            filter_.initialized() ? filter_.step(ctx.k, ctx.t_s, a, p) : filter_.initialize(ctx.k, ctx.t_s, a, p);
        to_msg(e, out_.value());
        report_counts(ctx);
    }

private:
    [[nodiscard]] std::string count_details() const override {
        const auto& r = filter_.rejections();
        return fmt::format("AirSample {}, AtmSample {}, before initialisation {} (total {})", r.air, r.atm,
                           rejected_before_init(), total());
    }

    framework::Input<msg::AirSample> air_{*this, topics::kAir};
    framework::Input<msg::AtmSample> atm_{*this, topics::kAtm};
    framework::Output<msg::AirDataEstimate> out_{*this, topics::kAirData};
};

}  // namespace

void register_nav_air(framework::ComponentRegistry& reg) {
    reg.add("nav_air", "air data filter: AirSample + AtmSample -> AirDataEstimate", framework::make_factory<NavAir>());
}

}  // namespace gdnav::nav
