#include "nav_files.hpp"

#include "framework/run_config.hpp"
#include "model/air_data_filter.hpp"
#include "model/attitude_filter.hpp"
#include "model/position_filter.hpp"

namespace gdnav::nav {

namespace {
// The variant used to check a tuning file's attitude and position sections where the component has none (nav_air):
// a variant never changes what a tuning section may contain.
config::Config builtin_variant() {
    return config::Config::parse(
        "attitude: {specific_force: baseline}\nposition: {horizontal: frozen_wind, vertical: pressure}\n",
        "built-in baseline variant");
}
}  // namespace

NavFiles load_nav_files(const config::Config& cfg, bool has_variant) {
    const auto dir = framework::config_dir();
    NavFiles f{config::Config::load(cfg.get_file("tuning", "nav/tuning.yaml", dir)),
               has_variant ? config::Config::load(cfg.get_file("variant", "nav/variants/baseline.yaml", dir))
                           : builtin_variant(),
               AidedAttitude::kPaper, DeniedAttitude::kPaper, InFlightAlignerSettings{}, 0.0};
    AirDataFilter{}.configure(f.tuning.child("air"), rnd::Stream{});
    AttitudeFilter{}.configure(f.tuning.child("attitude"), f.variant.child("attitude"), rnd::Stream{});
    PositionFilter position;
    position.configure(f.tuning.child("position"), f.variant.child("position"), rnd::Stream{});
    f.gnss_loss_timeout_s = position.tuning().gnss_loss_timeout_s;
    f.aided = f.variant.get_choice("aided_attitude", "paper", {"paper", "gnss_ins"}) == "gnss_ins"
                  ? AidedAttitude::kGnssIns
                  : AidedAttitude::kPaper;
    if (f.variant.get_choice("denied_attitude", "paper", {"paper", "gnss_ins"}) == "gnss_ins") {
        if (f.aided != AidedAttitude::kGnssIns)
            f.variant.fail("aided_attitude", "denied_attitude: gnss_ins needs aided_attitude: gnss_ins");
        f.denied = DeniedAttitude::kGnssIns;
    }
    if (position.tuning().wind_from_gnss_ins && f.denied != DeniedAttitude::kGnssIns)
        f.variant.child("position").fail("wind_at_loss", "gnss_ins needs denied_attitude: gnss_ins (the joint "
                                                         "estimator's wind and air-data offsets)");
    if (const auto g = f.variant.optional_child("gnss_ins")) {
        if (f.aided != AidedAttitude::kGnssIns)
            f.variant.fail("aided_attitude", "a gnss_ins section needs aided_attitude: gnss_ins");
        f.gnss_ins = parse_in_flight_alignment(*g);
    }
    f.tuning.finish();
    f.variant.finish();
    return f;
}

std::optional<InitMode> init_override(const config::Config& cfg) {
    if (!cfg.has("init_mode")) return std::nullopt;
    return cfg.get_choice("init_mode", {"measurements", "alignment"}) == "alignment" ? InitMode::kAlignment
                                                                                      : InitMode::kMeasurements;
}

}  // namespace gdnav::nav
