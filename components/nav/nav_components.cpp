#include "nav_components.hpp"

#include "model/air_data_filter.hpp"
#include "model/attitude_filter.hpp"
#include "model/position_filter.hpp"
#include "nav_convert.hpp"
#include "runtime/run_config.hpp"

namespace gdnav::nav {

using runtime::Input;
using runtime::Lag;
using runtime::Output;

namespace {

config::Config load_section(const config::Config& cfg, const char* key, const char* fallback, const char* section) {
    const config::Config file = config::Config::load(runtime::config_dir() / cfg.get_string(key, fallback));
    return file.child(section);
}

std::optional<InitMode> init_override(const config::Config& cfg) {
    if (!cfg.has("init_mode")) return std::nullopt;
    return cfg.get_choice("init_mode", {"measurements", "alignment"}) == "alignment" ? InitMode::kAlignment
                                                                                      : InitMode::kMeasurements;
}

// ------------------------------------------------------------------------------------------------ nav_air
class NavAir final : public runtime::Component {
public:
    using Component::Component;
    void configure(const config::Config& cfg, const runtime::RunInfo&, rnd::Stream& stream) override {
        const config::Config tuning = load_section(cfg, "tuning", "nav/tuning.yaml", "air");
        filter_.configure(tuning, stream);
        tuning.finish();
    }
    void step(const runtime::StepContext& ctx) override {
        if (!air_.available() || !atm_.available()) return;  // a lost sensor: hold the last estimate
        const AirSample a = from_msg(air_.get());
        const AtmSample p = from_msg(atm_.get());
        const AirDataEstimate e =
            filter_.initialized() ? filter_.step(ctx.k, ctx.t_s, a, p) : filter_.initialize(ctx.k, ctx.t_s, a, p);
        to_msg(e, out_.value());
    }

private:
    Input<msg::AirSample> air_{*this, topics::kAir};
    Input<msg::AtmSample> atm_{*this, topics::kAtm};
    Output<msg::AirDataEstimate> out_{*this, topics::kAirData};
    AirDataFilter filter_;
};

// ------------------------------------------------------------------------------------------------ nav_att
class NavAtt final : public runtime::Component {
public:
    using Component::Component;
    void configure(const config::Config& cfg, const runtime::RunInfo&, rnd::Stream& stream) override {
        const config::Config tuning = load_section(cfg, "tuning", "nav/tuning.yaml", "attitude");
        const config::Config variant = load_section(cfg, "variant", "nav/variants/baseline.yaml", "attitude");
        filter_.configure(tuning, variant, stream.child("filter"));
        if (auto m = init_override(cfg)) {
            AttitudeFilter::Tuning t = filter_.tuning();
            t.init_mode = *m;
            filter_.configure(t, stream.child("filter"));
        }
    }
    void step(const runtime::StepContext& ctx) override {
        if (!imu_.available() || !mag_.available()) return;
        const ImuSample imu = from_msg(imu_.get());
        const MagSample mag = from_msg(mag_.get());
        if (pos_prev_.available()) last_pos_ = from_msg(pos_prev_.get());
        AttitudeEstimate e;
        if (filter_.initialized()) {
            e = filter_.step(ctx.k, ctx.t_s, imu, mag, last_pos_);
        } else {
            if (!air_.available() || !gnss_.available() || !gnss_.get().fix_valid()) return;  // wait for a fix
            const Alignment align = alignment_from_msg(imu_.get(), &mag_.get());
            e = filter_.initialize(ctx.k, ctx.t_s, imu, mag, from_msg(air_.get()), from_msg(gnss_.get()), &align);
        }
        to_msg(e, out_.value());
    }

private:
    Input<msg::ImuSample> imu_{*this, topics::kImu};
    Input<msg::MagSample> mag_{*this, topics::kMag};
    Input<msg::AirDataEstimate> air_{*this, topics::kAirData};
    Input<msg::GnssSample> gnss_{*this, topics::kGnss};
    Input<msg::PositionEstimate> pos_prev_{*this, topics::kPosition, Lag::Previous};
    Output<msg::AttitudeEstimate> out_{*this, topics::kAttitude};
    AttitudeFilter filter_;
    PositionEstimate last_pos_;
};

// ------------------------------------------------------------------------------------------------ nav_pos
class NavPos final : public runtime::Component {
public:
    using Component::Component;
    void configure(const config::Config& cfg, const runtime::RunInfo&, rnd::Stream& stream) override {
        const config::Config tuning = load_section(cfg, "tuning", "nav/tuning.yaml", "position");
        const config::Config variant = load_section(cfg, "variant", "nav/variants/baseline.yaml", "position");
        filter_.configure(tuning, variant, stream.child("filter"));
        if (auto m = init_override(cfg)) {
            PositionFilter::Tuning t = filter_.tuning();
            t.init_mode = *m;
            filter_.configure(t, stream.child("filter"));
        }
    }
    void step(const runtime::StepContext& ctx) override {
        if (!imu_.available() || !air_.available() || !att_.available()) return;
        GnssSample gnss;  // fix_valid false unless a sample is there
        if (gnss_.available()) {
            gnss = from_msg(gnss_.get());
        } else if (gnss_.lost() && !publisher_dead_) {
            publisher_dead_ = true;
            filter_.set_gnss_publisher_dead();
        }
        const ImuSample imu = from_msg(imu_.get());
        const AirDataEstimate air = from_msg(air_.get());
        const AttitudeEstimate att = from_msg(att_.get());
        PositionEstimate e;
        if (filter_.initialized()) {
            e = filter_.step(ctx.k, ctx.t_s, imu, gnss, air, att);
        } else {
            if (!gnss.fix_valid) return;  // wait for the first fix
            const Alignment align = alignment_from_msg(imu_.get());  // E_acc only
            e = filter_.initialize(ctx.k, ctx.t_s, imu, gnss, air, att, &align);
        }
        if (e.gnss_lost_event)
            publish_status(publisher_dead_ ? "GNSS lost: the GNSS publisher was declared dead"
                                           : "GNSS lost: no valid fix for more than 1.5 s");
        to_msg(e, out_.value());
    }

private:
    Input<msg::ImuSample> imu_{*this, topics::kImu};
    Input<msg::GnssSample> gnss_{*this, topics::kGnss};
    Input<msg::AirDataEstimate> air_{*this, topics::kAirData};
    Input<msg::AttitudeEstimate> att_{*this, topics::kAttitude};
    Output<msg::PositionEstimate> out_{*this, topics::kPosition};
    PositionFilter filter_;
    bool publisher_dead_{false};
};


}  // namespace

void register_nav_components(runtime::ComponentRegistry& reg) {
    reg.add("nav_air", "air data filter: AirSample + AtmSample -> AirDataEstimate", runtime::make_factory<NavAir>());
    reg.add("nav_att", "attitude filter: IMU + magnetometer (+ p_n of k-1) -> AttitudeEstimate", runtime::make_factory<NavAtt>());
    reg.add("nav_pos", "position filter, GNSS-aided then GNSS-denied -> PositionEstimate", runtime::make_factory<NavPos>());
}

}  // namespace gdnav::nav
