// ViewerChannels on a component without any executor: inputs found or declared on the owner, messages only at
// decimated steps and only for the channels whose inputs are there, CDR that decodes back (Fast CDR type support,
// as gdnav's reader) to the values of the bound samples.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "framework/executor_access.hpp"
#include "io/recording/record_file.hpp"
#include "msgs/messages.hpp"
#include "io/viewer/viewer_channels.hpp"
#include "io/viewer/viewer_math.hpp"
#include "msgs/viewer_messages.hpp"

using namespace gdnav;

namespace {

class Owner final : public framework::Component {
public:
    Owner() : Component("owner") {}
    void configure(const config::Config&, const framework::RunInfo&, rnd::Stream&) override {}
    void step(const framework::StepContext&) override {}
    framework::Input<msg::Truth> truth{*this, topics::kTruth};
};

template <class T>
T decode(const std::vector<std::uint8_t>& cdr) {
    io::recording::SampleDecoder dec(msg::message_ops<T>());
    T out;
    EXPECT_TRUE(dec.decode(cdr.data(), static_cast<std::uint32_t>(cdr.size()), &out));
    return out;
}

framework::InputBase* find_input(Owner& o, const std::string& topic) {
    for (framework::InputBase* in : o.inputs())
        if (in->topic() == topic) return in;
    return nullptr;
}

}  // namespace

TEST(ViewerChannels, ListsSevenChannelsWithSchemasAViewerRecognises) {
    const auto& c = io::viewer::viewer_channels();
    ASSERT_EQ(c.size(), 7u);
    EXPECT_EQ(c[0].topic, "/viewer/true/fix");
    EXPECT_EQ(c[1].topic, "/viewer/est/fix");
    EXPECT_EQ(c[0].schema_name, "foxglove::LocationFix");
    EXPECT_EQ(c[2].schema_name, "foxglove::FrameTransform");
    EXPECT_EQ(c[4].schema_name, "gdnav::viewer::NavErrors");
    EXPECT_EQ(c[5].topic, "/viewer/true/pose");
    EXPECT_EQ(c[6].topic, "/viewer/est/pose");
    EXPECT_EQ(c[5].schema_name, "foxglove::PoseInFrame");
    EXPECT_EQ(c[6].schema_name, "foxglove::PoseInFrame");
    for (const auto& ch : c) {
        EXPECT_EQ(ch.schema_encoding, "omgidl");
        EXPECT_EQ(ch.message_encoding, "cdr");
        // Self-contained: no preprocessor line (#include) for the viewer's parser to resolve.
        EXPECT_EQ(ch.schema.find("\n#"), std::string::npos) << ch.topic;
        EXPECT_NE(ch.schema.front(), '#') << ch.topic;
        EXPECT_TRUE(io::viewer::is_viewer_channel(ch.topic, ch.schema_name, "omgidl", "cdr"));
    }
    EXPECT_NE(c[0].schema.find("struct LocationFix"), std::string::npos);
    EXPECT_NE(c[5].schema.find("struct PoseInFrame"), std::string::npos);
    EXPECT_NE(c[4].schema.find("struct NavErrors"), std::string::npos);
    EXPECT_FALSE(io::viewer::is_viewer_channel("/viewer/true/fix", "foxglove::FrameTransform", "omgidl", "cdr"));
    EXPECT_FALSE(io::viewer::is_viewer_channel("/imu", "foxglove::LocationFix", "omgidl", "cdr"));
}

TEST(ViewerChannels, ReusesTheOwnersInputsAndEncodesAtDecimatedSteps) {
    Owner owner;
    io::viewer::ViewerChannels vc(owner, io::viewer::ViewerOptions{10});
    // Truth was the owner's; the three estimates are declared on it.
    ASSERT_EQ(owner.inputs().size(), 4u);
    EXPECT_EQ(find_input(owner, topics::kTruth), &owner.truth);

    msg::Truth t;
    t.lat_rad(math::deg2rad(45.0));
    t.lon_rad(math::deg2rad(10.0));
    t.h_m(1000.0);
    t.q_nb({1.0, 0.0, 0.0, 0.0});  // heading north, level
    t.v_n_mps({30.0, 40.0, 0.0});
    msg::AttitudeEstimate q;
    const math::Quat q_est = math::quat_from_euler({math::deg2rad(2.0), 0.0, 0.0});
    q.q_nb({q_est.w(), q_est.x(), q_est.y(), q_est.z()});
    msg::PositionEstimate p;
    p.lat_rad(t.lat_rad());
    p.lon_rad(t.lon_rad());
    p.h_m(1003.0);
    p.v_n_mps({30.0, 40.0, 0.0});
    p.gnss_denied(true);
    msg::AirDataEstimate a;
    framework::ExecutorAccess::bind(owner.truth, &t);

    std::vector<io::viewer::ViewerMessage> out;
    // Step 10 with Truth only: the three true channels.
    vc.encode({10, 0.1, 0.01, false}, 100'000'000ULL, out);
    ASSERT_EQ(out.size(), 3u);
    EXPECT_EQ(out[0].first, 0u);
    EXPECT_EQ(out[1].first, 2u);
    EXPECT_EQ(out[2].first, 5u);
    const auto fix = decode<foxglove::LocationFix>(out[0].second);
    EXPECT_DOUBLE_EQ(fix.latitude(), 45.0);
    EXPECT_DOUBLE_EQ(fix.longitude(), 10.0);
    EXPECT_EQ(fix.altitude(), 1000.0);
    EXPECT_EQ(fix.timestamp().sec(), 0u);
    EXPECT_EQ(fix.timestamp().nsec(), 100'000'000u);
    const auto tf = decode<foxglove::FrameTransform>(out[1].second);
    EXPECT_EQ(tf.parent_frame_id(), "enu");
    EXPECT_EQ(tf.child_frame_id(), "body_true");
    EXPECT_EQ(tf.translation().x(), 0.0);  // the first true position is the origin
    EXPECT_NEAR(tf.rotation().w(), std::sqrt(0.5), 1e-15);  // heading north: 90 deg about up
    EXPECT_NEAR(tf.rotation().z(), std::sqrt(0.5), 1e-15);
    const auto pose = decode<foxglove::PoseInFrame>(out[2].second);  // the transform's pose, in the world frame
    EXPECT_EQ(pose.frame_id(), "enu");
    EXPECT_EQ(pose.timestamp().nsec(), 100'000'000u);
    EXPECT_EQ(pose.pose_().position().x(), tf.translation().x());
    EXPECT_EQ(pose.pose_().position().z(), tf.translation().z());
    EXPECT_EQ(pose.pose_().orientation().w(), tf.rotation().w());
    EXPECT_EQ(pose.pose_().orientation().z(), tf.rotation().z());

    // Step 15: between decimated steps, nothing.
    out.clear();
    framework::ExecutorAccess::bind(*find_input(owner, topics::kAttitude), &q);
    framework::ExecutorAccess::bind(*find_input(owner, topics::kPosition), &p);
    framework::ExecutorAccess::bind(*find_input(owner, topics::kAirData), &a);
    vc.encode({15, 0.15, 0.01, false}, 150'000'000ULL, out);
    EXPECT_TRUE(out.empty());

    // Step 20 with every input: all seven, the errors as metrics computes them.
    vc.encode({20, 0.2, 0.01, false}, 200'000'000ULL, out);
    ASSERT_EQ(out.size(), 7u);
    EXPECT_EQ(out[3].first, 1u);
    const auto est = decode<foxglove::LocationFix>(out[3].second);
    EXPECT_EQ(est.altitude(), 1003.0);
    EXPECT_EQ(est.frame_id(), "body_est");
    const auto est_tf = decode<foxglove::FrameTransform>(out[4].second);
    EXPECT_NEAR(est_tf.translation().z(), 3.0, 1e-6);  // 3 m above the origin
    EXPECT_EQ(out[5].first, 6u);
    const auto est_pose = decode<foxglove::PoseInFrame>(out[5].second);
    EXPECT_EQ(est_pose.pose_().position().z(), est_tf.translation().z());
    EXPECT_EQ(est_pose.pose_().orientation().w(), est_tf.rotation().w());
    EXPECT_EQ(out[6].first, 4u);
    const auto e = decode<viewer::NavErrors>(out[6].second);
    EXPECT_NEAR(e.att_err_deg(), 2.0, 1e-12);
    EXPECT_NEAR(e.yaw_err_deg(), 2.0, 1e-12);
    EXPECT_EQ(e.alt_err_m(), 3.0);
    EXPECT_EQ(e.hor_err_m(), 0.0);
    EXPECT_EQ(e.gs_err_mps(), 0.0);
    EXPECT_TRUE(e.gnss_denied());
    EXPECT_EQ(e.t_s(), 0.2);
}
