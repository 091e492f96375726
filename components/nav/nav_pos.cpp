// nav_pos: the position filter (model/position_filter.hpp), GNSS-aided then GNSS-denied; optionally the alignment
// monitor (model/alignment_monitor.hpp, `alignment_check`) and the in-flight alignment of nav_att
// (`follow_in_flight_alignment: true`: the aligned flag and, at its hand-over, its accelerometer errors, from
// gdnav/NavHandover), both published on gdnav/NavAlignment; with the variant's `wind_at_loss: gnss_ins` the wind and
// air-data offsets of the joint estimator (gdnav/NavHandover) for the denied phase.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include <spdlog/spdlog.h>

#include "framework/msg_eigen.hpp"
#include "math/rotation.hpp"
#include "model/alignment_monitor.hpp"
#include "model/position_filter.hpp"
#include "msgs/alignment_messages.hpp"
#include "msgs/messages.hpp"
#include "nav_convert.hpp"
#include "nav_files.hpp"

namespace gdnav::nav {

using framework::Input;
using framework::Output;

namespace {

class NavPos final : public VariantFilterComponent<PositionFilter, kPositionSection> {
public:
    using VariantFilterComponent::VariantFilterComponent;
    void configure(const config::Config& cfg, const framework::RunInfo& run, rnd::Stream& stream) override {
        (void)configure_filter(cfg, stream);
        if (auto c = cfg.optional_child("alignment_check")) monitor_.emplace(parse_alignment_criteria(*c), run.dt_s);
        if (cfg.has("in_flight_alignment"))
            cfg.fail("in_flight_alignment", "nav_att runs the in-flight alignment and publishes it on "
                                            "gdnav/NavHandover: give the section to nav_att only, and "
                                            "`follow_in_flight_alignment: true` to nav_pos");
        follow_ = cfg.get_bool("follow_in_flight_alignment", false);
        if (follow_ || filter_.tuning().wind_from_gnss_ins)
            handover_ = std::make_unique<Input<msg::NavHandover>>(*this, topics::kHandover);
        if (monitor_ || follow_)  // only then is there an alignment topic
            align_out_ = std::make_unique<Output<msg::NavAlignment>>(*this, topics::kAlignment);
    }
    void step(const framework::StepContext& ctx) override {
        // The step at which nav_att's estimator declares itself aligned (with the in-flight alignment also its
        // hand-over): the position filter starts again from its accelerometer errors, as it ran on the estimator's
        // coarse attitude until then. A hand-over at the GNSS loss leaves the position filter alone: it goes denied
        // itself at that step.
        const bool hand_over = follow_ && handover_->available() && handover_->get().aligned() && !aligned_step_seen_;
        if (hand_over) aligned_step_seen_ = true;
        if (filter_.tuning().wind_from_gnss_ins) take_gnss_ins_calibration(ctx);
        const std::uint64_t accepted_before = filter_.gate_accepted();
        step_filter(ctx);
        if (hand_over && filter_.initialized()) realign(ctx);
        if (monitor_ && filter_.initialized() && att_.available()) step_monitor(ctx, accepted_before);
        if (follow_) publish_aligner_flag(ctx);
    }

private:
    // `wind_at_loss: gnss_ins`: the estimator's latest wind and air-data offsets, which the filter keeps from the loss
    // on; said once if the filter goes denied without them (it then keeps its own wind).
    void take_gnss_ins_calibration(const framework::StepContext& ctx) {
        if (handover_->available() && handover_->get().started()) {
            const msg::NavHandover& h = handover_->get();
            filter_.set_gnss_ins_calibration(to_vec3(h.wind_n_mps()), to_vec3(h.air_data_offsets()));
        } else if (!filter_.has_gnss_ins_calibration() && !calibration_missing_said_ && filter_.gnss_denied()) {
            calibration_missing_said_ = true;
            publish_status(fmt::format("GNSS-denied at t = {:.2f} s without the joint estimator's wind (no "
                                       "gdnav/NavHandover): the position filter keeps its own",
                                       ctx.t_s));
        }
    }

    // The position filter starts again with the in-flight alignment's E_acc (the attitude filter has just started
    // again from its attitude; the hand-over step always has a fix).
    void realign(const framework::StepContext& ctx) {
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
        const msg::NavHandover& h = handover_->get();
        const PositionEstimate e = filter_.initialize(ctx.k, ctx.t_s, imu, gnss, air, att, to_vec3(h.acc_err_b_mps2()),
                                                      to_vec3(h.acc_err_sigma_mps2()));
        to_msg(e, out_.value());
    }
    // Following the in-flight alignment, the aligned flag and the sigmas are nav_att's estimator's (gdnav/NavHandover).
    void publish_aligner_flag(const framework::StepContext& ctx) {
        const bool have = handover_->available() && handover_->get().started();
        const bool aligned = have && handover_->get().aligned();
        if (aligned && !aligned_seen_) {
            aligned_seen_ = true;
            publish_status(fmt::format("aligned at t = {:.2f} s (in-flight alignment: tilt sigma {:.3f} deg, heading "
                                       "sigma {:.3f} deg)",
                                       ctx.t_s, math::rad2deg(handover_->get().tilt_sigma_rad()),
                                       math::rad2deg(handover_->get().heading_sigma_rad())));
        }
        auto& o = align_out_->value();
        o.aligned(aligned);
        o.t_aligned_s(aligned ? handover_->get().t_aligned_s() : 0.0);
        o.tilt_sigma_rad(have ? handover_->get().tilt_sigma_rad() : 0.0);
        o.yaw_sigma_rad(have ? handover_->get().heading_sigma_rad() : 0.0);
        if (!monitor_) o.gnss_nis_mean(0.0);
    }

    void step_monitor(const framework::StepContext& ctx, std::uint64_t accepted_before) {
        const msg::AttitudeEstimate& att = att_.get();
        if (!monitor_->started()) {
            const auto& p = filter_.aided_covariance();
            monitor_->start(std::max(att.att_sigma_rad()[0], att.att_sigma_rad()[1]),
                            std::sqrt(std::max(p(aided::kE, aided::kE), p(aided::kE + 1, aided::kE + 1))));
        }
        const double d2 = filter_.gate_d2_last();
        const bool was_aligned = monitor_->aligned();
        monitor_->step(ctx.t_s, framework::to_vec3(imu_.get().f_b_mps2()), framework::to_quat(att.q_nb()),
                       att.att_sigma_rad()[2], filter_.gate_accepted() > accepted_before ? &d2 : nullptr,
                       filter_.gnss_denied());
        if (monitor_->aligned() && !was_aligned && !handover_)  // else the aligner's hand-over is the event
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

    void step_filter(const framework::StepContext& ctx) {
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
    std::unique_ptr<Input<msg::NavHandover>> handover_;  // following the in-flight alignment, or wind_at_loss: gnss_ins
    bool follow_{false};                                  // follow_in_flight_alignment
    bool calibration_missing_said_{false};
    bool aligned_step_seen_{false};
    bool aligned_seen_{false};
    std::unique_ptr<Output<msg::NavAlignment>> align_out_;

    Input<msg::ImuSample> imu_{*this, topics::kImu};
    Input<msg::GnssSample> gnss_{*this, topics::kGnss};
    Input<msg::AirDataEstimate> air_{*this, topics::kAirData};
    Input<msg::AttitudeEstimate> att_{*this, topics::kAttitude};
    Output<msg::PositionEstimate> out_{*this, topics::kPosition};
    bool publisher_dead_{false};
};

}  // namespace

void register_nav_pos(framework::ComponentRegistry& reg) {
    reg.add("nav_pos", "position filter, GNSS-aided then GNSS-denied -> PositionEstimate",
            framework::make_factory<NavPos>());
}

}  // namespace gdnav::nav
