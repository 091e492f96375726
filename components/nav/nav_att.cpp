// nav_att: the attitude filter (model/attitude_filter.hpp); optionally the joint GNSS/INS estimator
// (model/in_flight_aligner.hpp) in front of it — the in-flight alignment, through the whole GNSS-aided phase with the
// variant gnss_calibration_handover, or in place of it for the whole run with keep_gnss_calibration — and the GNSS
// yaw estimator (model/yaw_gsf.hpp).
// When the estimator runs, nav_att is its only owner: it publishes gdnav/NavHandover every step, from which nav_pos
// takes the aligned flag and, at the hand-over, the accelerometer errors (docs/navigation.md, "In-flight fine
// alignment"), and with `wind_at_loss: gnss_ins` the wind and air-data offsets of the GNSS loss.
#include <algorithm>
#include <memory>
#include <optional>
#include <string>

#include <spdlog/fmt/fmt.h>

#include "framework/msg_eigen.hpp"
#include "math/rotation.hpp"
#include "model/attitude_filter.hpp"
#include "model/gnss_loss_monitor.hpp"
#include "model/in_flight_aligner.hpp"
#include "model/yaw_gsf.hpp"
#include "msgs/alignment_messages.hpp"
#include "msgs/messages.hpp"
#include "nav_convert.hpp"
#include "nav_files.hpp"

namespace gdnav::nav {

using framework::Input;
using framework::Lag;
using framework::Output;

namespace {

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

GnssYaw parse_gnss_yaw(const config::Config& c) {
    GnssYaw y;
    y.gsf = YawGsf(parse_yaw_gsf(c));
    y.fuse_sigma_max_rad = c.get_angle_deg("fuse_sigma_max_deg", config::Range{0.1, 30.0});
    y.fuse_sigma_min_rad = c.get_angle_deg("fuse_sigma_min_deg", config::Range{0.01, 30.0});
    y.fuse_accel_min_mps2 = c.get_double("fuse_accel_min_mps2", config::Range{0.0, 20.0});
    c.finish();
    return y;
}

// The joint GNSS/INS estimator: the in-flight alignment (`in_flight_alignment: {...}`, in_flight_aligner.hpp; only
// after a truth-free start, handed over once aligned), or with `aided_attitude: gnss_ins` in the variant file
// through the whole GNSS-aided phase, handed over at the GNSS loss (or, with `denied_attitude: gnss_ins`, never:
// it goes on after the loss), from the truth-free start or from the sensors' published alignment, with the
// variant's `gnss_ins` settings and over them the component's section, if given.
std::optional<InFlightAligner> configure_estimator(const config::Config& cfg, const NavFiles& files, InitMode mode,
                                                   double dt_s) {
    const auto c = cfg.optional_child("in_flight_alignment");
    if (files.aided == AidedAttitude::kGnssIns)
        return InFlightAligner(c ? parse_in_flight_alignment(*c, files.gnss_ins) : files.gnss_ins, dt_s,
                               files.denied == DeniedAttitude::kGnssIns ? HandOver::kNever : HandOver::kAtGnssLoss);
    if (!c) return std::nullopt;
    if (mode != InitMode::kMeasurements)
        cfg.fail("in_flight_alignment", "needs init_mode: measurements (it replaces the sensors' published alignment)");
    return InFlightAligner(parse_in_flight_alignment(*c), dt_s, HandOver::kAtAlignment);
}

class NavAtt final : public VariantFilterComponent<AttitudeFilter, kAttitudeSection> {
public:
    using VariantFilterComponent::VariantFilterComponent;
    void configure(const config::Config& cfg, const framework::RunInfo& run, rnd::Stream& stream) override {
        const NavFiles files = configure_filter(cfg, stream);
        if (auto c = cfg.optional_child("yaw_from_gnss")) yaw_.emplace(parse_gnss_yaw(*c));
        estimator_ = configure_estimator(cfg, files, filter_.tuning().init_mode, run.dt_s);
        if (estimator_ && yaw_)
            cfg.fail("yaw_from_gnss", "not with in_flight_alignment or aided_attitude: gnss_ins (the joint estimator "
                                      "has the GNSS heading itself)");
        if (estimator_) {
            loss_ = GnssLossMonitor(files.gnss_loss_timeout_s);
            handover_out_ = std::make_unique<Output<msg::NavHandover>>(*this, topics::kHandover);
        }
    }
    void step(const framework::StepContext& ctx) override {
        if (estimator_ && estimator_->running()) {
            step_estimator(ctx);
            return;
        }
        step_filter(ctx);
        if (yaw_ && filter_.initialized()) step_yaw();
    }

private:
    // Until the hand-over nav_att publishes the estimator's attitude (the attitude filter does not run); at the
    // hand-over the attitude filter starts from it: from its alignment as from the sensors' published one (in-flight
    // alignment), or from its state and joint covariance at the GNSS loss. With HandOver::kNever the GNSS loss only
    // ends the estimator's GNSS-aided phase, and nav_att publishes it to the end.
    void step_estimator(const framework::StepContext& ctx) {
        InFlightAligner& est = *estimator_;
        if (!imu_.available() || !mag_.available() || !air_.available()) return;
        GnssSample fix;  // fix_valid false unless a sample is there
        if (gnss_.available()) fix = from_msg(gnss_.get());
        const AirDataEstimate air = from_msg(air_.get());
        std::optional<Alignment> published;
        if (filter_.tuning().init_mode == InitMode::kAlignment)
            published = alignment_from_msg(imu_.get(), &mag_.get());
        const bool was_started = est.started();
        const bool aligned = step_in_flight_aligner(est, ctx.t_s, from_msg(imu_.get()), from_msg(mag_.get()), fix,
                                                    AirSample{air.tas_mps, air.aoa_rad, air.aos_rad},
                                                    published ? &*published : nullptr);
        if (!est.started()) return;
        if (!was_started) loss_.reset(ctx.t_s);
        AttitudeEstimate e;
        if (aligned) {
            e = filter_.realign(ctx.k, ctx.t_s, from_msg(imu_.get()), est.alignment());
            publish_status(fmt::format("in-flight alignment at t = {:.2f} s (tilt sigma {:.3f} deg, heading sigma "
                                       "{:.3f} deg): the attitude filter starts from it",
                                       ctx.t_s, math::rad2deg(est.tilt_sigma_rad()),
                                       math::rad2deg(est.heading_sigma_rad())));
        } else if (est.mode() != HandOver::kAtAlignment && !est.handed_over() && gnss_lost(ctx, fix)) {
            // The GNSS loss: the estimator goes on (HandOver::kNever) or hands over to the attitude filter.
            est.hand_over(ctx.t_s);
            const bool goes_on = est.mode() == HandOver::kNever;
            e = goes_on ? est.estimate(ctx.k, ctx.t_s) : filter_.hand_over(ctx.k, ctx.t_s, est.handover());
            publish_status(fmt::format("GNSS lost at t = {:.2f} s: {} (tilt sigma {:.3f} deg, heading sigma "
                                       "{:.3f} deg)",
                                       ctx.t_s,
                                       goes_on ? "the GNSS/INS estimator goes on with air data and the magnetometer"
                                               : "the attitude filter takes over from the GNSS/INS estimator",
                                       math::rad2deg(est.tilt_sigma_rad()), math::rad2deg(est.heading_sigma_rad())));
        } else {
            e = est.estimate(ctx.k, ctx.t_s);
        }
        to_msg(e, out_.value());
        out_est_ = e;
        publish_handover();
    }

    // The GNSS loss as the position filter sees it: its own rule on the same fixes (no valid fix for
    // gnss_loss_timeout_s, or the publisher declared dead), or its previous estimate already denied (its
    // chi-square gate distrusted the source), so in the nominal case both switch at the same step. After a
    // truth-free start the position filter's gate is not trusted before the estimator is aligned: it runs on the
    // estimator's coarse attitude until then and may reject good fixes (nav_pos starts again at the alignment).
    bool gnss_lost(const framework::StepContext& ctx, const GnssSample& fix) {
        if (gnss_.lost()) loss_.set_publisher_dead();
        loss_.update(ctx.t_s, fix.fix_valid && checks::gnss_fix_ok(fix));
        const bool pos_trusted = estimator_->aligned() || filter_.tuning().init_mode == InitMode::kAlignment;
        const bool pos_denied = pos_trusted && pos_prev_.available() && pos_prev_.get().gnss_denied();
        return loss_.denied() || pos_denied;
    }

    void publish_handover() {
        const InFlightAligner& est = *estimator_;
        auto& o = handover_out_->value();
        o.started(est.started());
        o.aligned(est.aligned());
        o.t_aligned_s(est.aligned() ? est.t_aligned_s() : 0.0);
        o.handed_over(est.handed_over());
        o.t_handed_over_s(est.handed_over() ? est.t_handed_over_s() : 0.0);
        o.at_gnss_loss(est.mode() != HandOver::kAtAlignment);
        o.tilt_sigma_rad(est.tilt_sigma_rad());
        o.heading_sigma_rad(est.heading_sigma_rad());
        const Alignment al = est.alignment();
        o.acc_err_b_mps2(to_array(al.acc_err_mps2));
        o.acc_err_sigma_mps2(to_array(al.acc_err_sigma_mps2));
        o.wind_n_mps(to_array(est.wind_n_mps()));
        o.air_data_offsets(to_array(est.air_offsets()));
    }

    void step_yaw() {
        const bool fix = gnss_.available() && gnss_.get().fix_valid();
        YawGsf& g = yaw_->gsf;
        if (!g.started()) {
            if (fix) g.start(to_vec3(gnss_.get().v_n_mps()));
            return;
        }
        const AttitudeEstimate& e = out_est_;
        g.predict(filter_.tuning().dt_s, to_vec3(imu_.get().w_b_rps()) - e.gyr_bias_rps,
                  to_vec3(imu_.get().f_b_mps2()), e.euler_rad.y(), e.euler_rad.z());
        if (!fix) return;
        g.update(to_vec3(gnss_.get().v_n_mps()));
        const double var = g.yaw_variance_rad2();
        if (var > yaw_->fuse_sigma_max_rad * yaw_->fuse_sigma_max_rad) return;
        if (g.turn_accel_mps2() < yaw_->fuse_accel_min_mps2) return;
        (void)filter_.fuse_yaw(g.yaw_rad(), std::max(var, yaw_->fuse_sigma_min_rad * yaw_->fuse_sigma_min_rad));
    }

    void step_filter(const framework::StepContext& ctx) {
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
    std::optional<InFlightAligner> estimator_;
    GnssLossMonitor loss_;
    std::unique_ptr<Output<msg::NavHandover>> handover_out_;
};

}  // namespace

void register_nav_att(framework::ComponentRegistry& reg) {
    reg.add("nav_att", "attitude filter: IMU + magnetometer (+ p_n of k-1) -> AttitudeEstimate",
            framework::make_factory<NavAtt>());
}

}  // namespace gdnav::nav
