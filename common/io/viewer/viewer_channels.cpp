#include "io/viewer/viewer_channels.hpp"

#include "io/mcap/mcap_format.hpp"
#include "io/run_series/series_columns.hpp"  // nav_recorder: the metrics views of Truth and the estimates
#include "msgs/messages.hpp"
#include "framework/msg_eigen.hpp"
#include "io/viewer/viewer_math.hpp"
#include "msgs/idl_text.hpp"
#include "msgs/viewer_messages.hpp"

namespace gdnav::io::viewer {

namespace {

using mcap::kCdr;
using mcap::kOmgIdl;
constexpr const char* kWorldFrame = "enu";

enum Index : std::size_t { kTrueFix, kEstFix, kTrueTf, kEstTf, kErrors, kTruePose, kEstPose, kCount };

template <class T>
void encode_message(std::size_t channel, const T& message, std::vector<ViewerMessage>& out) {
    out.emplace_back(channel, std::vector<std::uint8_t>{});
    msg::message_ops<T>().serialize(&message, out.back().second);
}

foxglove::Time stamp_of(std::uint64_t log_time_ns) {
    const TimeParts p = time_parts(log_time_ns);
    foxglove::Time t;
    t.sec(p.sec);
    t.nsec(p.nsec);
    return t;
}

foxglove::LocationFix location_fix(const foxglove::Time& stamp, const char* frame, double lat_rad, double lon_rad,
                                   double h_m) {
    foxglove::LocationFix f;
    f.timestamp(stamp);
    f.frame_id(frame);
    f.latitude(math::rad2deg(lat_rad));
    f.longitude(math::rad2deg(lon_rad));
    f.altitude(h_m);
    f.position_covariance({});
    f.position_covariance_type(foxglove::PositionCovarianceType::UNKNOWN);
    return f;
}

// The body frame's pose in `enu`: ENU offset from the origin, and the FLU body axes' rotation (viewer_math.hpp).
void set_pose(foxglove::Vector3& position, foxglove::Quaternion& orientation, const math::Vec3& enu_m,
              const math::Quat& q_nb) {
    position.x(enu_m.x());
    position.y(enu_m.y());
    position.z(enu_m.z());
    const math::Quat q = quat_enu_flu(q_nb);
    orientation.x(q.x());
    orientation.y(q.y());
    orientation.z(q.z());
    orientation.w(q.w());
}

foxglove::FrameTransform frame_transform(const foxglove::Time& stamp, const char* child, const math::Vec3& enu_m,
                                         const math::Quat& q_nb) {
    foxglove::FrameTransform tf;
    tf.timestamp(stamp);
    tf.parent_frame_id(kWorldFrame);
    tf.child_frame_id(child);
    set_pose(tf.translation(), tf.rotation(), enu_m, q_nb);
    return tf;
}

foxglove::PoseInFrame pose_in_frame(const foxglove::Time& stamp, const math::Vec3& enu_m, const math::Quat& q_nb) {
    foxglove::PoseInFrame p;
    p.timestamp(stamp);
    p.frame_id(kWorldFrame);
    set_pose(p.pose_().position(), p.pose_().orientation(), enu_m, q_nb);
    return p;
}

}  // namespace

const std::vector<ViewerChannel>& viewer_channels() {
    static const std::vector<ViewerChannel> channels = [] {
        const std::string fox(msg::idl_text::foxglove_schemas());
        const std::string own(msg::idl_text::gdnav_viewer());
        std::vector<ViewerChannel> c(kCount);
        c[kTrueFix] = {"/viewer/true/fix", "foxglove::LocationFix", kOmgIdl, fox, kCdr};
        c[kEstFix] = {"/viewer/est/fix", "foxglove::LocationFix", kOmgIdl, fox, kCdr};
        c[kTrueTf] = {"/viewer/true/tf", "foxglove::FrameTransform", kOmgIdl, fox, kCdr};
        c[kEstTf] = {"/viewer/est/tf", "foxglove::FrameTransform", kOmgIdl, fox, kCdr};
        c[kErrors] = {"/viewer/nav_errors", "gdnav::viewer::NavErrors", kOmgIdl, own, kCdr};
        c[kTruePose] = {"/viewer/true/pose", "foxglove::PoseInFrame", kOmgIdl, fox, kCdr};
        c[kEstPose] = {"/viewer/est/pose", "foxglove::PoseInFrame", kOmgIdl, fox, kCdr};
        return c;
    }();
    return channels;
}

const std::vector<std::string>& viewer_input_topics() {
    static const std::vector<std::string> topics{topics::kTruth, topics::kAttitude, topics::kPosition,
                                                 topics::kAirData};
    return topics;
}

bool is_viewer_channel(const std::string& topic, const std::string& schema_name, const std::string& schema_encoding,
                       const std::string& message_encoding) {
    for (const auto& c : viewer_channels())
        if (c.topic == topic && c.schema_name == schema_name && c.schema_encoding == schema_encoding &&
            c.message_encoding == message_encoding)
            return true;
    return false;
}

ViewerChannels::ViewerChannels(framework::Component& owner, ViewerOptions options) : options_(options) {
    if (options_.decimation == 0) options_.decimation = 1;
    truth_ = &input(owner, topics::kTruth, msg::message_ops<msg::Truth>());
    att_ = &input(owner, topics::kAttitude, msg::message_ops<msg::AttitudeEstimate>());
    pos_ = &input(owner, topics::kPosition, msg::message_ops<msg::PositionEstimate>());
    air_ = &input(owner, topics::kAirData, msg::message_ops<msg::AirDataEstimate>());
}

ViewerChannels::~ViewerChannels() = default;

const framework::InputBase& ViewerChannels::input(framework::Component& owner, const std::string& topic,
                                                const msg::MessageOps& ops) {
    for (const framework::InputBase* in : owner.inputs())
        if (in->topic() == topic && in->lag() == framework::Lag::Same) return *in;
    owned_.push_back(std::make_unique<framework::InputBase>(owner, topic, framework::Lag::Same, ops));
    return *owned_.back();
}

void ViewerChannels::encode(const framework::StepContext& ctx, std::uint64_t log_time_ns,
                            std::vector<ViewerMessage>& out) {
    if (!truth_->available()) return;
    const auto& t = *static_cast<const msg::Truth*>(truth_->data_ptr());
    if (!have_origin_) {  // as nav_recorder: the first true position, its radii for the horizontal errors
        have_origin_ = true;
        origin_ = {t.lon_rad(), t.lat_rad(), t.h_m()};
        radii0_ = earth::radii(t.lat_rad());
    }
    if (ctx.k % options_.decimation != 0) return;
    const foxglove::Time stamp = stamp_of(log_time_ns);
    const earth::Geodetic true_pos{t.lon_rad(), t.lat_rad(), t.h_m()};
    const math::Vec3 true_enu = enu_offset_m(origin_, true_pos);
    const math::Quat true_q = framework::to_quat(t.q_nb());
    encode_message(kTrueFix, location_fix(stamp, "body_true", t.lat_rad(), t.lon_rad(), t.h_m()), out);
    encode_message(kTrueTf, frame_transform(stamp, "body_true", true_enu, true_q), out);
    encode_message(kTruePose, pose_in_frame(stamp, true_enu, true_q), out);
    if (!att_->available() || !pos_->available() || !air_->available()) return;
    const auto& q = *static_cast<const msg::AttitudeEstimate*>(att_->data_ptr());
    const auto& p = *static_cast<const msg::PositionEstimate*>(pos_->data_ptr());
    const auto& a = *static_cast<const msg::AirDataEstimate*>(air_->data_ptr());
    const earth::Geodetic est_pos{p.lon_rad(), p.lat_rad(), p.h_m()};
    encode_message(kEstFix, location_fix(stamp, "body_est", p.lat_rad(), p.lon_rad(), p.h_m()), out);
    const math::Vec3 est_enu = enu_offset_m(origin_, est_pos);
    const math::Quat est_q = framework::to_quat(q.q_nb());
    encode_message(kEstTf, frame_transform(stamp, "body_est", est_enu, est_q), out);
    encode_message(kEstPose, pose_in_frame(stamp, est_enu, est_q), out);
    const NavErrorValues v =
        nav_error_values(run_series::estimate_state(a, q, p), run_series::truth_state(t), radii0_);
    gdnav::viewer::NavErrors e;
    e.t_s(ctx.t_s);
    e.att_err_deg(v.att_err_deg);
    e.yaw_err_deg(v.yaw_err_deg);
    e.pitch_err_deg(v.pitch_err_deg);
    e.bank_err_deg(v.bank_err_deg);
    e.hor_err_m(v.hor_err_m);
    e.cross_err_m(v.cross_err_m);
    e.along_err_m(v.along_err_m);
    e.alt_err_m(v.alt_err_m);
    e.vn_err_mps(v.vn_err_mps);
    e.ve_err_mps(v.ve_err_mps);
    e.gs_err_mps(v.gs_err_mps);
    e.tas_err_mps(v.tas_err_mps);
    e.gnss_denied(p.gnss_denied());
    encode_message(kErrors, e, out);
}

}  // namespace gdnav::io::viewer
