#include "nav_components.hpp"

#include <cstdint>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include <spdlog/spdlog.h>

#include "model/air_data_filter.hpp"
#include "model/alignment_monitor.hpp"
#include "model/attitude_filter.hpp"
#include "model/in_flight_aligner.hpp"
#include "model/position_filter.hpp"
#include "model/yaw_gsf.hpp"
#include "nav_convert.hpp"
#include "framework/run_config.hpp"
#include "framework/msg_eigen.hpp"
#include "msgs/alignment_messages.hpp"
#include "rejection_report.hpp"

namespace gdnav::nav {

using runtime::Input;
using runtime::Lag;
using runtime::Output;

namespace {

// The tuning file holds one section per filter (air, attitude, position) and a variant file one per filter it changes
// (attitude, position). Each file is validated whole wherever it is read: every section is parsed by its filter's
// parser and finish() runs on the whole file, so an unknown or misspelt key anywhere in it — also at the top level or
// in another filter's section — is an error, whichever nav components the run has.
struct NavFiles {
    config::Config tuning;   // the whole tuning file
    config::Config variant;  // the whole variant file
};

// The variant used to check a tuning file's attitude and position sections where the component has none (nav_air):
// a variant never changes what a tuning section may contain.
config::Config builtin_variant() {
    return config::Config::parse(
        "attitude: {specific_force: baseline}\nposition: {horizontal: frozen_wind, vertical: pressure}\n",
        "built-in baseline variant");
}

NavFiles load_nav_files(const config::Config& cfg, bool has_variant) {
    const auto dir = runtime::config_dir();
    NavFiles f{config::Config::load(cfg.get_file("tuning", "nav/tuning.yaml", dir)),
               has_variant ? config::Config::load(cfg.get_file("variant", "nav/variants/baseline.yaml", dir))
                           : builtin_variant()};
    AirDataFilter{}.configure(f.tuning.child("air"), rnd::Stream{});
    AttitudeFilter{}.configure(f.tuning.child("attitude"), f.variant.child("attitude"), rnd::Stream{});
    PositionFilter{}.configure(f.tuning.child("position"), f.variant.child("position"), rnd::Stream{});
    f.tuning.finish();
    f.variant.finish();
    return f;
}

std::optional<InitMode> init_override(const config::Config& cfg) {
    if (!cfg.has("init_mode")) return std::nullopt;
    return cfg.get_choice("init_mode", {"measurements", "alignment"}) == "alignment" ? InitMode::kAlignment
                                                                                      : InitMode::kMeasurements;
}

// A nav component around one filter; its rejections are by default the filter's and those before initialisation.
template <class Filter>
class FilterComponent : public RejectionReporting {
public:
    using RejectionReporting::RejectionReporting;

protected:
    [[nodiscard]] std::uint64_t total() const override {
        return filter_.rejections().total() + rejected_before_init();
    }

    Filter filter_;
};

// nav_att and nav_pos: a filter that has a variant, configured from its `Section` of both nav files, then with the
// component's `init_mode` override, if any.
template <class Filter, const char* Section>
class VariantFilterComponent : public FilterComponent<Filter> {
public:
    using FilterComponent<Filter>::FilterComponent;
    void configure(const config::Config& cfg, const runtime::RunInfo&, rnd::Stream& stream) override {
        const NavFiles files = load_nav_files(cfg, true);
        this->filter_.configure(files.tuning.child(Section), files.variant.child(Section), stream.child("filter"));
        if (auto m = init_override(cfg)) {
            typename Filter::Tuning t = this->filter_.tuning();
            t.init_mode = *m;
            this->filter_.configure(t, stream.child("filter"));
        }
    }
};

constexpr char kAttitudeSection[] = "attitude";
constexpr char kPositionSection[] = "position";

// ------------------------------------------------------------------------------------------------ nav_air
class NavAir final : public FilterComponent<AirDataFilter> {
public:
    using FilterComponent::FilterComponent;
    void configure(const config::Config& cfg, const runtime::RunInfo&, rnd::Stream& stream) override {
        const NavFiles files = load_nav_files(cfg, false);
        filter_.configure(files.tuning.child("air"), stream);
    }
    void step(const runtime::StepContext& ctx) override {
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

    Input<msg::AirSample> air_{*this, topics::kAir};
    Input<msg::AtmSample> atm_{*this, topics::kAtm};
    Output<msg::AirDataEstimate> out_{*this, topics::kAirData};
};

// ------------------------------------------------------------------------------------------------ nav_att
// Heading from GNSS velocity fused into the attitude filter (nav_att option `yaw_from_gnss`): the estimator's keys
// (yaw_gsf.cpp) and fuse_sigma_max_deg [0.1, 30] (3: fuse only once the bank has decided), fuse_sigma_min_deg
// [0.01, 30] (1: floor of the fused sigma, as the estimate's errors are correlated from fix to fix),
// fuse_accel_min_mps2 [0, 20] (fuse only while turning: the levelled horizontal specific force over the fix period,
// YawGsf::turn_accel_mps2, at least this; 0 fuses in straight flight too).
struct GnssYaw {
    YawGsf gsf;
    double fuse_sigma_max_rad{0.0};
    double fuse_sigma_min_rad{0.0};
    double fuse_accel_min_mps2{0.0};
};

// The in-flight fine alignment (`in_flight_alignment: {...}`, in_flight_aligner.hpp) in nav_att and nav_pos: both
// run the same aligner on the same samples, so both hand over at the same step; only after a truth-free start.
std::optional<InFlightAligner> configure_aligner(const config::Config& cfg, InitMode mode, double dt_s) {
    const auto c = cfg.optional_child("in_flight_alignment");
    if (!c) return std::nullopt;
    if (mode != InitMode::kMeasurements)
        cfg.fail("in_flight_alignment", "needs init_mode: measurements (it replaces the sensors' published alignment)");
    return InFlightAligner(parse_in_flight_alignment(*c), dt_s);
}

bool step_aligner(InFlightAligner& a, double t_s, const Input<msg::ImuSample>& imu, const Input<msg::MagSample>& mag,
                  const Input<msg::GnssSample>& gnss, const Input<msg::AirDataEstimate>& air) {
    if (!imu.available() || !mag.available() || !air.available()) return false;
    GnssSample fix;  // fix_valid false unless a sample is there
    if (gnss.available()) fix = from_msg(gnss.get());
    const AirDataEstimate e = from_msg(air.get());
    return step_in_flight_aligner(a, t_s, from_msg(imu.get()), from_msg(mag.get()), fix,
                                  AirSample{e.tas_mps, e.aoa_rad, e.aos_rad});
}

class NavAtt final : public VariantFilterComponent<AttitudeFilter, kAttitudeSection> {
public:
    using VariantFilterComponent::VariantFilterComponent;
    void configure(const config::Config& cfg, const runtime::RunInfo& run, rnd::Stream& stream) override {
        VariantFilterComponent::configure(cfg, run, stream);
        if (auto c = cfg.optional_child("yaw_from_gnss")) {
            yaw_.emplace();
            yaw_->gsf = YawGsf(parse_yaw_gsf(*c));
            yaw_->fuse_sigma_max_rad = c->get_angle_deg("fuse_sigma_max_deg", config::Range{0.1, 30.0});
            yaw_->fuse_sigma_min_rad = c->get_angle_deg("fuse_sigma_min_deg", config::Range{0.01, 30.0});
            yaw_->fuse_accel_min_mps2 = c->get_double("fuse_accel_min_mps2", config::Range{0.0, 20.0});
            c->finish();
        }
        aligner_ = configure_aligner(cfg, filter_.tuning().init_mode, run.dt_s);
        if (aligner_ && yaw_)
            cfg.fail("yaw_from_gnss", "not with in_flight_alignment (the aligner has the GNSS heading itself)");
    }
    void step(const runtime::StepContext& ctx) override {
        if (aligner_ && !aligner_->handed_over()) {
            step_aligned_start(ctx);
            return;
        }
        step_filter(ctx);
        if (yaw_ && filter_.initialized()) step_yaw();
    }

private:
    // Until the hand-over nav_att publishes the aligner's attitude (the attitude filter does not run); at the
    // hand-over the attitude filter starts from the aligner's alignment, as from the sensors' published one.
    void step_aligned_start(const runtime::StepContext& ctx) {
        const bool hand_over = step_aligner(*aligner_, ctx.t_s, imu_, mag_, gnss_, air_);
        if (!aligner_->started()) return;
        AttitudeEstimate e;
        if (hand_over) {
            e = filter_.realign(ctx.k, ctx.t_s, from_msg(imu_.get()), aligner_->alignment());
            publish_status(fmt::format("in-flight alignment at t = {:.2f} s (tilt sigma {:.3f} deg, heading sigma "
                                       "{:.3f} deg): the attitude filter starts from it",
                                       ctx.t_s, math::rad2deg(aligner_->tilt_sigma_rad()),
                                       math::rad2deg(aligner_->heading_sigma_rad())));
        } else {
            e = aligner_->estimate(ctx.k, ctx.t_s);
        }
        to_msg(e, out_.value());
        out_est_ = e;
    }

    void step_yaw() {
        const bool fix = gnss_.available() && gnss_.get().fix_valid();
        YawGsf& g = yaw_->gsf;
        if (!g.started()) {
            if (fix) g.start(runtime::to_vec3(gnss_.get().v_n_mps()));
            return;
        }
        const AttitudeEstimate& e = out_est_;
        g.predict(filter_.tuning().dt_s, runtime::to_vec3(imu_.get().w_b_rps()) - e.gyr_bias_rps,
                  runtime::to_vec3(imu_.get().f_b_mps2()), e.euler_rad.y(), e.euler_rad.z());
        if (!fix) return;
        g.update(runtime::to_vec3(gnss_.get().v_n_mps()));
        const double var = g.yaw_variance_rad2();
        if (var > yaw_->fuse_sigma_max_rad * yaw_->fuse_sigma_max_rad) return;
        if (g.turn_accel_mps2() < yaw_->fuse_accel_min_mps2) return;
        (void)filter_.fuse_yaw(g.yaw_rad(), std::max(var, yaw_->fuse_sigma_min_rad * yaw_->fuse_sigma_min_rad));
    }

    void step_filter(const runtime::StepContext& ctx) {
        if (!imu_.available() || !mag_.available()) return;
        const ImuSample imu = from_msg(imu_.get());
        const MagSample mag = from_msg(mag_.get());
        if (pos_prev_.available()) last_pos_ = from_msg(pos_prev_.get());
        AttitudeEstimate e;
        if (filter_.initialized()) {
            e = filter_.step(ctx.k, ctx.t_s, imu, mag, last_pos_);
        } else {
            if (!air_.available() || !gnss_.available() || !gnss_.get().fix_valid()) return;  // wait for a fix
            const GnssSample gnss = from_msg(gnss_.get());
            if (!checks::imu_ok(imu) || !checks::mag_ok(mag) || !checks::gnss_fix_ok(gnss)) {
                reject_before_init();  // wait for good samples
                return;
            }
            const Alignment align = alignment_from_msg(imu_.get(), &mag_.get());
            e = filter_.initialize(ctx.k, ctx.t_s, imu, mag, from_msg(air_.get()), gnss, &align);
        }
        to_msg(e, out_.value());
        out_est_ = e;
        report_counts(ctx);
    }

private:
    [[nodiscard]] std::string count_details() const override {
        const auto& r = filter_.rejections();
        return fmt::format("ImuSample {}, MagSample {}, PositionEstimate (p_n) {}, before initialisation {} (total {})",
                           r.imu, r.mag, r.position, rejected_before_init(), total());
    }

    Input<msg::ImuSample> imu_{*this, topics::kImu};
    Input<msg::MagSample> mag_{*this, topics::kMag};
    Input<msg::AirDataEstimate> air_{*this, topics::kAirData};
    Input<msg::GnssSample> gnss_{*this, topics::kGnss};
    Input<msg::PositionEstimate> pos_prev_{*this, topics::kPosition, Lag::Previous};
    Output<msg::AttitudeEstimate> out_{*this, topics::kAttitude};
    PositionEstimate last_pos_;
    AttitudeEstimate out_est_;
    std::optional<GnssYaw> yaw_;
    std::optional<InFlightAligner> aligner_;
};

// ------------------------------------------------------------------------------------------------ nav_pos
class NavPos final : public VariantFilterComponent<PositionFilter, kPositionSection> {
public:
    using VariantFilterComponent::VariantFilterComponent;
    void configure(const config::Config& cfg, const runtime::RunInfo& run, rnd::Stream& stream) override {
        VariantFilterComponent::configure(cfg, run, stream);
        if (auto c = cfg.optional_child("alignment_check")) monitor_.emplace(parse_alignment_criteria(*c), run.dt_s);
        aligner_ = configure_aligner(cfg, filter_.tuning().init_mode, run.dt_s);
        if (aligner_) mag_ = std::make_unique<Input<msg::MagSample>>(*this, topics::kMag);
        if (monitor_ || aligner_)  // only then is there an alignment topic
            align_out_ = std::make_unique<Output<msg::NavAlignment>>(*this, topics::kAlignment);
    }
    void step(const runtime::StepContext& ctx) override {
        const bool hand_over = aligner_ && step_aligner(*aligner_, ctx.t_s, imu_, *mag_, gnss_, air_);
        const std::uint64_t accepted_before = filter_.gate_accepted();
        step_filter(ctx);
        if (hand_over && filter_.initialized()) realign(ctx);
        if (monitor_ && filter_.initialized() && att_.available()) step_monitor(ctx, accepted_before);
        if (aligner_) publish_aligner_flag(ctx, hand_over);
    }

private:
    // The position filter starts again with the in-flight alignment's E_acc (the attitude filter has just started
    // again from its attitude; the hand-over step always has a fix).
    void realign(const runtime::StepContext& ctx) {
        GnssSample gnss;  // fix_valid false unless a sample is there
        if (gnss_.available()) gnss = from_msg(gnss_.get());
        const AirDataEstimate air = from_msg(air_.get());
        const AttitudeEstimate att = att_.available() ? from_msg(att_.get()) : AttitudeEstimate{};
        if (!gnss.fix_valid || !att_.available() || !checks::gnss_fix_ok(gnss) || !checks::air_estimate_ok(air) ||
            !checks::attitude_estimate_ok(att)) {
            publish_status("in-flight alignment: the position filter keeps its own E_acc (no good fix, air data or "
                           "attitude sample at the hand-over)");
            return;
        }
        const ImuSample imu = from_msg(imu_.get());
        const Alignment al = aligner_->alignment();
        const PositionEstimate e =
            filter_.initialize(ctx.k, ctx.t_s, imu, gnss, air, att, al.acc_err_mps2, al.acc_err_sigma_mps2);
        to_msg(e, out_.value());
    }
    // With the in-flight alignment the aligned flag is its hand-over, and the sigmas are its own.
    void publish_aligner_flag(const runtime::StepContext& ctx, bool hand_over) {
        if (hand_over)
            publish_status(fmt::format("aligned at t = {:.2f} s (in-flight alignment: tilt sigma {:.3f} deg, heading "
                                       "sigma {:.3f} deg)",
                                       ctx.t_s, math::rad2deg(aligner_->tilt_sigma_rad()),
                                       math::rad2deg(aligner_->heading_sigma_rad())));
        auto& o = align_out_->value();
        o.aligned(aligner_->handed_over());
        o.t_aligned_s(aligner_->handed_over() ? aligner_->t_handed_over_s() : 0.0);
        o.tilt_sigma_rad(aligner_->started() ? aligner_->tilt_sigma_rad() : 0.0);
        o.yaw_sigma_rad(aligner_->started() ? aligner_->heading_sigma_rad() : 0.0);
        if (!monitor_) o.gnss_nis_mean(0.0);
    }

    void step_monitor(const runtime::StepContext& ctx, std::uint64_t accepted_before) {
        const msg::AttitudeEstimate& att = att_.get();
        if (!monitor_->started()) {
            const auto& p = filter_.aided_covariance();
            monitor_->start(std::max(att.att_sigma_rad()[0], att.att_sigma_rad()[1]),
                            std::sqrt(std::max(p(aided::kE, aided::kE), p(aided::kE + 1, aided::kE + 1))));
        }
        const double d2 = filter_.gate_d2_last();
        const bool was_aligned = monitor_->aligned();
        monitor_->step(ctx.t_s, runtime::to_vec3(imu_.get().f_b_mps2()), runtime::to_quat(att.q_nb()),
                       att.att_sigma_rad()[2], filter_.gate_accepted() > accepted_before ? &d2 : nullptr,
                       filter_.gnss_denied());
        if (monitor_->aligned() && !was_aligned && !aligner_)  // else the aligner's hand-over is the event
            publish_status(fmt::format("aligned at t = {:.2f} s: tilt sigma {:.3f} deg, yaw sigma {:.3f} deg, mean "
                                       "GNSS d2 {:.2f}",
                                       ctx.t_s, math::rad2deg(monitor_->tilt_sigma_rad()),
                                       math::rad2deg(monitor_->yaw_sigma_rad()), monitor_->nis_mean()));
        auto& o = align_out_->value();
        o.aligned(monitor_->aligned());
        o.t_aligned_s(monitor_->t_aligned_s());
        o.tilt_sigma_rad(monitor_->tilt_sigma_rad());
        o.yaw_sigma_rad(monitor_->yaw_sigma_rad());
        o.gnss_nis_mean(monitor_->nis_mean());
    }

    void step_filter(const runtime::StepContext& ctx) {
        if (!imu_.available() || !air_.available() || !att_.available()) return;
        GnssSample gnss;  // fix_valid false unless a sample is there
        if (gnss_.available()) {
            gnss = from_msg(gnss_.get());
            if (publisher_dead_) {  // the publisher was restarted
                publisher_dead_ = false;
                filter_.set_gnss_publisher_alive();
            }
        } else if (gnss_.lost() && !publisher_dead_) {
            publisher_dead_ = true;
            filter_.set_gnss_publisher_dead();
        }
        const ImuSample imu = from_msg(imu_.get());
        const AirDataEstimate air = from_msg(air_.get());
        const AttitudeEstimate att = from_msg(att_.get());
        PositionEstimate e;
        if (filter_.initialized()) {
            const std::uint64_t gate_before = filter_.rejections().gnss_gate;
            e = filter_.step(ctx.k, ctx.t_s, imu, gnss, air, att);
            if (filter_.rejections().gnss_gate > gate_before && ctx.t_s - t_gate_status_s_ >= kPeriod_s) {
                t_gate_status_s_ = ctx.t_s;
                publish_status(fmt::format("GNSS fix rejected by the chi-square gate: d2 = {:.1f} > {} ({} rejected)",
                                           filter_.gate_d2_last(), filter_.tuning().gate_chi2_6dof,
                                           filter_.rejections().gnss_gate));
            }
        } else {
            if (!gnss.fix_valid) return;  // wait for the first fix
            if (!checks::gnss_fix_ok(gnss) || !checks::imu_ok(imu) || !checks::air_estimate_ok(air) ||
                !checks::attitude_estimate_ok(att)) {
                reject_before_init();  // wait for good samples
                return;
            }
            const Alignment align = alignment_from_msg(imu_.get());  // E_acc only
            e = filter_.initialize(ctx.k, ctx.t_s, imu, gnss, air, att, &align);
        }
        if (e.gnss_lost_event) {
            t_lost_s_ = ctx.t_s;
            switch (filter_.denied_reason()) {
                case PositionFilter::DeniedReason::kPublisherDead:
                    publish_status("GNSS lost: the GNSS publisher was declared dead");
                    break;
                case PositionFilter::DeniedReason::kUntrusted:
                    publish_status(fmt::format("GNSS lost: fix source untrusted after {} consecutive fixes rejected "
                                               "by the chi-square gate",
                                               filter_.tuning().gate_max_consecutive_rejections));
                    break;
                default:
                    publish_status(fmt::format("GNSS lost: no valid fix for more than {} s",
                                               filter_.tuning().gnss_loss_timeout_s));
            }
        }
        if (e.gnss_reacquired_event)
            publish_status(fmt::format("GNSS re-acquired: back to GNSS-aided after {} consecutive consistent fixes "
                                       "({:.2f} s denied)",
                                       filter_.tuning().reacquire_fixes, ctx.t_s - t_lost_s_));
        report_counts(ctx);
        to_msg(e, out_.value());
    }

public:
    void finish(bool) override {
        if (total() > 0 || filter_.reacquisitions() > 0) {
            spdlog::info("[{}] {}", name(), counts(true));
        } else {
            spdlog::debug("[{}] {}", name(), counts(true));
        }
    }

private:
    [[nodiscard]] std::string count_details() const override {
        const auto& r = filter_.rejections();
        return fmt::format(
            "ImuSample {}, GnssSample (invalid) {}, AirDataEstimate {}, AttitudeEstimate {}, before initialisation {}; "
            "GNSS fixes rejected by the chi-square gate {} (accepted {}, largest accepted d2 {:.1f}), refused for "
            "re-acquisition {}; re-acquisitions {} (total rejected {})",
            r.imu, r.gnss_invalid, r.air, r.attitude, rejected_before_init(), r.gnss_gate, filter_.gate_accepted(),
            filter_.gate_d2_max_accepted(), r.gnss_reacquire, filter_.reacquisitions(), total());
    }
    double t_gate_status_s_{-std::numeric_limits<double>::infinity()};
    double t_lost_s_{0.0};
    std::optional<AlignmentMonitor> monitor_;
    std::optional<InFlightAligner> aligner_;
    std::unique_ptr<Input<msg::MagSample>> mag_;  // the aligner's only
    std::unique_ptr<Output<msg::NavAlignment>> align_out_;

    Input<msg::ImuSample> imu_{*this, topics::kImu};
    Input<msg::GnssSample> gnss_{*this, topics::kGnss};
    Input<msg::AirDataEstimate> air_{*this, topics::kAirData};
    Input<msg::AttitudeEstimate> att_{*this, topics::kAttitude};
    Output<msg::PositionEstimate> out_{*this, topics::kPosition};
    bool publisher_dead_{false};
};


}  // namespace

void register_nav_components(runtime::ComponentRegistry& reg) {
    reg.add("nav_air", "air data filter: AirSample + AtmSample -> AirDataEstimate", runtime::make_factory<NavAir>());
    reg.add("nav_att", "attitude filter: IMU + magnetometer (+ p_n of k-1) -> AttitudeEstimate", runtime::make_factory<NavAtt>());
    reg.add("nav_pos", "position filter, GNSS-aided then GNSS-denied -> PositionEstimate", runtime::make_factory<NavPos>());
}

}  // namespace gdnav::nav
