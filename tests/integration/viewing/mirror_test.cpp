// Decimated mirrors over real DDS (dds/host/mirror.hpp, docs/protocol.md §2.2): during a distributed run with the
// live view at its default decimation,
//  * the live bridge's data readers are all on the mirrors (`<topic>/every_10_steps`), none on a topic itself — so
//    the producers' writers of the topics the run steps on do not deliver to it (seen from outside through DDS
//    discovery: the topic name of every reader each participant announces);
//  * a reader outside the run on a mirror gets exactly the steps k % 10 == 0, every one of them, and each sample is
//    byte for byte the topic's own sample of that step;
//  * a topic written by an external member (which need not write mirrors) is read from the topic itself.
// What the mirrors save on the wire is measured, not tested (docs/runtime.md, "Mirrors for the observers").
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>
#include <vector>

#include <fastdds/dds/domain/DomainParticipantListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/domain/DomainParticipant.hpp>

#include "outside_reader.hpp"
#include "process_util.hpp"
#include "dds/dds_context.hpp"
#include "msgs/messages.hpp"
#include "dds/host/mirror.hpp"
#include "framework/run_config.hpp"
#include "framework/topic_types.hpp"

using namespace gdnav::testing;
namespace msg = gdnav::msg;
namespace framework = gdnav::framework;
using namespace eprosima::fastdds::dds;

namespace {

// Every participant's name and the topics of the readers it announces.
struct Discovered final : DomainParticipantListener {
    std::mutex m;
    std::map<std::string, std::string> name_of;              // GUID prefix -> participant name
    std::map<std::string, std::set<std::string>> readers_of;  // GUID prefix -> reader topics
    static std::string key(const eprosima::fastrtps::rtps::GuidPrefix_t& p) {
        std::ostringstream s;
        s << p;
        return s.str();
    }
    void on_participant_discovery(DomainParticipant*, eprosima::fastrtps::rtps::ParticipantDiscoveryInfo&& info) override {
        std::lock_guard<std::mutex> l(m);
        name_of[key(info.info.m_guid.guidPrefix)] = info.info.m_participantName.to_string();
    }
    void on_subscriber_discovery(DomainParticipant*, eprosima::fastrtps::rtps::ReaderDiscoveryInfo&& info) override {
        std::lock_guard<std::mutex> l(m);
        readers_of[key(info.info.guid().guidPrefix)].insert(info.info.topicName().to_string());
    }
    std::set<std::string> readers_named(const std::string& participant) {
        std::lock_guard<std::mutex> l(m);
        for (const auto& [prefix, name] : name_of)
            if (name == participant) return readers_of[prefix];
        return {};
    }
};

// Takes every valid sample of `r` into by_step (serialised bytes by step).
void drain(DataReader& r, const msg::MessageOps& ops, void* sample,
           std::map<std::uint64_t, std::vector<std::uint8_t>>& by_step, int& repeated) {
    SampleInfo info;
    while (r.take_next_sample(sample, &info) == eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK) {
        if (!info.valid_data) continue;
        std::vector<std::uint8_t> bytes;
        ops.serialize(sample, bytes);
        repeated += by_step.count(ops.step_of(sample)) ? 1 : 0;
        by_step[ops.step_of(sample)] = std::move(bytes);
    }
}

}  // namespace

TEST(Mirror, TheLiveBridgeReadsOnlyMirrorsAndAMirrorIsEveryTenthStepOfItsTopicBitForBit) {
    constexpr int kDomain = 152;  // integration tests run one at a time (RUN_SERIAL)
    constexpr std::uint64_t kSteps = 2000;
    framework::register_gdnav_topics();
    const msg::MessageOps* ops = framework::find_topic(gdnav::topics::kImu);
    ASSERT_NE(ops, nullptr);
    Discovered discovered;  // outlives the participant
    gdnav::dds::DdsContext dds(kDomain, framework::config_dir() / "dds" / "gdnav_profiles.xml", "gdnav.test.mirror");
    ASSERT_EQ(dds.participant()->set_listener(&discovered), eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK);
    // The test reads outside the lockstep, so its readers keep the whole run (outside_reader.hpp).
    const auto depth = static_cast<std::int32_t>(kSteps) + 16;
    DataReader* mirror = whole_run_reader(dds, gdnav::dds::mirror_topic(gdnav::topics::kImu), *ops, depth);
    DataReader* topic = whole_run_reader(dds, gdnav::topics::kImu, *ops, depth);
    ASSERT_NE(mirror, nullptr);
    ASSERT_NE(topic, nullptr);

    const auto out = temp_dir("mirror");
    const int port = free_port();
    ASSERT_GT(port, 0);
    const pid_t launcher = start({GDNAV_GDNAV_EXE, "run", "--scenario", "default", "--layout", "distributed",
                                  "--steps", std::to_string(kSteps), "--domain", std::to_string(kDomain), "--live",
                                  std::to_string(port), "--out", out.string()},
                                 out.string() + ".log");
    std::map<std::uint64_t, std::vector<std::uint8_t>> from_mirror, from_topic;
    int repeated = 0, code = -1;
    void* sample = ops->create();
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(180);
    while (code == -1 && std::chrono::steady_clock::now() < deadline) {
        drain(*mirror, *ops, sample, from_mirror, repeated);
        drain(*topic, *ops, sample, from_topic, repeated);
        code = wait_for(launcher, 0.0);
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    if (code == -1) code = wait_for(launcher, 5.0);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the last samples in flight
    drain(*mirror, *ops, sample, from_mirror, repeated);
    drain(*topic, *ops, sample, from_topic, repeated);
    ops->destroy(sample);
    ASSERT_EQ(code, 0) << read_file(out.string() + ".log");

    // The bridge's process announced its data readers on the mirrors only (and its control readers).
    const std::set<std::string> bridge = discovered.readers_named("gdnav.live");
    ASSERT_FALSE(bridge.empty()) << "the live bridge's participant was not discovered";
    std::size_t mirrors = 0;
    for (const auto& t : bridge) {
        std::printf("live bridge reads %s\n", t.c_str());
        if (t == gdnav::topics::kTick || t == gdnav::topics::kRunControl || t == gdnav::topics::kStatus) continue;
        EXPECT_EQ(framework::find_topic(t), nullptr) << "the bridge reads the topic " << t << " itself, not its mirror";
    }
    for (const auto& t : framework::known_topics()) mirrors += bridge.count(gdnav::dds::mirror_topic(t));
    EXPECT_EQ(mirrors, framework::known_topics().size()) << "the bridge reads every data topic from its mirror";

    // The mirror: every 10th step from its first sample on (it matched before step 0), bit for bit the topic's.
    ASSERT_FALSE(from_mirror.empty());
    EXPECT_EQ(repeated, 0);
    std::uint64_t expect = from_mirror.begin()->first;
    EXPECT_EQ(expect, 0u);
    for (const auto& [step, bytes] : from_mirror) {
        ASSERT_EQ(step, expect) << "a step is missing, or a step that is not a multiple of 10";
        expect += gdnav::dds::kMirrorStride;
        auto it = from_topic.find(step);
        ASSERT_NE(it, from_topic.end()) << "step " << step << " not read from the topic itself";
        EXPECT_EQ(bytes, it->second) << "step " << step;
    }
    EXPECT_EQ(from_mirror.rbegin()->first, kSteps - gdnav::dds::kMirrorStride);
    EXPECT_EQ(from_topic.size(), kSteps);
    std::printf("mirror of %s: %zu samples (steps 0..%llu every %llu), each equal to the topic's; %zu from the topic\n",
                gdnav::topics::kImu, from_mirror.size(), static_cast<unsigned long long>(from_mirror.rbegin()->first),
                static_cast<unsigned long long>(gdnav::dds::kMirrorStride), from_topic.size());
}

TEST(Mirror, AnInputWrittenByAnExternalMemberIsReadFromTheTopicItself) {
    constexpr int kDomain = 153;
    Discovered discovered;
    gdnav::dds::DdsContext dds(kDomain, framework::config_dir() / "dds" / "gdnav_profiles.xml",
                               "gdnav.test.mirror-external");
    ASSERT_EQ(dds.participant()->set_listener(&discovered), eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK);
    const auto out = temp_dir("mirror-external");
    const int port = free_port();
    ASSERT_GT(port, 0);
    // Scenario #2 with the controller outside gdnav (the client library's example, docs/external.md).
    const PairResult p = run_pair({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--layout", "distributed", "--steps",
                                   "2000", "--external", "control", "--live", std::to_string(port), "--domain",
                                   std::to_string(kDomain), "--out", out.string()},
                                  {std::string(GDNAV_EXAMPLES_BIN) + "/gdnav-example-control", "--domain",
                                   std::to_string(kDomain)},
                                  out, 180.0);
    ASSERT_EQ(p.run_code, 0) << p.run_log << "\n--- member:\n" << p.member_log;
    const std::set<std::string> bridge = discovered.readers_named("gdnav.live");
    ASSERT_FALSE(bridge.empty()) << "the live bridge's participant was not discovered";
    for (const auto& t : framework::known_topics()) {
        if (t == std::string(gdnav::topics::kControls)) {
            EXPECT_TRUE(bridge.count(t)) << "the external member's topic is not read from the topic itself";
            EXPECT_FALSE(bridge.count(gdnav::dds::mirror_topic(t))) << "nobody writes the mirror of " << t;
        } else {
            EXPECT_TRUE(bridge.count(gdnav::dds::mirror_topic(t))) << t << " is not read from its mirror";
            EXPECT_FALSE(bridge.count(t)) << t << " is read from the topic itself";
        }
    }
}
