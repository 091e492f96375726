// The default DDS profile (config/dds/gdnav_profiles.xml) as Fast DDS actually loads it: UDPv4 only, no shared memory
// and no data sharing between processes (a SIGKILLed process must not be able to abort a healthy one through a
// shared-memory mutex, docs/runtime.md "Transports"), the data writers keep Fast DDS's default heartbeat period (a
// short one slows long UDP runs down) while the clock's control writers repair within 100 ms and the members' within
// 500 ms, and the data writers suppress NACKs for 100 ms (docs/runtime.md "NACK suppression"). Guards against an edit
// of the XML silently bringing any of it back; and an observer's reader is best-effort.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>

#include "dds/dds_context.hpp"
#include "dds/socket_buffers.hpp"
#include "msgs/messages.hpp"
#include "framework/run_config.hpp"

using namespace gdnav::msg;
using namespace gdnav::framework;
using namespace gdnav::dds;
using namespace eprosima::fastdds::dds;

TEST(DdsProfile, DefaultProfileUsesUdpOnlyWithoutSharedMemory) {
    const auto file = config_dir() / "dds" / "gdnav_profiles.xml";
    DdsContext dds(200 + static_cast<int>(getpid() % 30), file, "gdnav.test.profile");
    const DomainParticipantQos pq = dds.participant()->get_qos();
    EXPECT_FALSE(pq.transport().use_builtin_transports);
    ASSERT_FALSE(pq.transport().user_transports.empty());
    for (const auto& t : pq.transport().user_transports)
        EXPECT_NE(dynamic_cast<eprosima::fastdds::rtps::UDPv4TransportDescriptor*>(t.get()), nullptr);
    // 4 MiB receive buffers: a member without inputs (replay) writes a whole window of steps at once (docs/runtime.md
    // "Socket receive buffers").
    EXPECT_EQ(udp_receive_buffer_asked(*dds.participant()), 4u << 20);

    for (const char* profile :
         {kDataWriterProfile, kControlWriterProfile, kMemberControlWriterProfile, kLatchedWriterProfile}) {
        SCOPED_TRACE(profile);
        DataWriter* w = dds.writer(std::string("gdnav_test/") + profile, message_ops<gdnav::msg::Tick>(), profile);
        EXPECT_EQ(w->get_qos().data_sharing().kind(), DataSharingKind::OFF);
        EXPECT_EQ(w->get_qos().reliability().kind, RELIABLE_RELIABILITY_QOS);
        // Heartbeat period: Fast DDS's 3 s on the data and latched writers (a short one made long runs stall); 100 ms
        // on the control writers, so that a Tick or status lost on a loaded machine is repaired well within
        // run.member_timeout_s (docs/runtime.md "Transports").
        // The members' control writers 500 ms: their status every 100 ms keeps them heartbeating to every host's
        // status reader, and 500 ms is still a third of the default run.member_timeout_s.
        const auto& hb = w->get_qos().reliable_writer_qos().times.heartbeatPeriod;
        if (std::string(profile) == kControlWriterProfile) {
            EXPECT_EQ(hb.seconds, 0);
            EXPECT_EQ(hb.nanosec, 100'000'000u);
        } else if (std::string(profile) == kMemberControlWriterProfile) {
            EXPECT_EQ(hb.seconds, 0);
            EXPECT_EQ(hb.nanosec, 500'000'000u);
        } else {
            EXPECT_EQ(hb.seconds, 3);
        }
        // NACK suppression: with Fast DDS's 0 every sample written woke the event thread (docs/runtime.md).
        const auto& nack = w->get_qos().reliable_writer_qos().times.nackSupressionDuration;
        // Data writers only: control writers (statuses before discovery completes) repair a first sample at once.
        EXPECT_EQ(nack.seconds, 0);
        EXPECT_EQ(nack.nanosec, std::string(profile) == kDataWriterProfile ? 100'000'000u : 0u);
    }
    for (const char* profile : {kDataReaderProfile, kControlReaderProfile, kLatchedReaderProfile}) {
        SCOPED_TRACE(profile);
        DataReader* r = dds.reader(std::string("gdnav_test_r/") + profile, message_ops<gdnav::msg::Tick>(), profile);
        EXPECT_EQ(r->get_qos().data_sharing().kind(), DataSharingKind::OFF);
    }
    // An observer's reader (Component::observer): the data profile with BEST_EFFORT reliability, the rest unchanged.
    DataReader* be = dds.reader("gdnav_test_r/observer", message_ops<gdnav::msg::Tick>(), kDataReaderProfile, 1, true);
    EXPECT_EQ(be->get_qos().reliability().kind, BEST_EFFORT_RELIABILITY_QOS);
    EXPECT_EQ(be->get_qos().history().depth, 72);
    EXPECT_EQ(be->get_qos().data_sharing().kind(), DataSharingKind::OFF);
    DataReader* rel = dds.reader("gdnav_test_r/member", message_ops<gdnav::msg::Tick>(), kDataReaderProfile);
    EXPECT_EQ(rel->get_qos().reliability().kind, RELIABLE_RELIABILITY_QOS);
}

// The other UDP profiles ask for the same buffers.
TEST(DdsProfile, UdpProfilesAskForFourMebibyteReceiveBuffers) {
    for (const char* name : {"lossy_link.xml", "two_hosts_udp.xml"}) {
        SCOPED_TRACE(name);
        DdsContext dds(200 + static_cast<int>(getpid() % 30), config_dir() / "dds" / name,
                       std::string("gdnav.test.") + name);
        EXPECT_EQ(udp_receive_buffer_asked(*dds.participant()), 4u << 20);
    }
}

// A kernel cap below the profile's buffers gives one line naming both figures and the sysctl; enough, or nothing to
// compare, gives none.
TEST(DdsProfile, AReceiveBufferCapBelowTheProfileIsNamedWithItsRemedy) {
    const std::string s = receive_buffer_shortfall(4u << 20, 212992);
    EXPECT_NE(s.find("capped at 212992 bytes"), std::string::npos) << s;
    EXPECT_NE(s.find("asks for 4194304"), std::string::npos) << s;
    EXPECT_NE(s.find("sysctl -w net.core.rmem_max=4194304"), std::string::npos) << s;
    EXPECT_EQ(receive_buffer_shortfall(4u << 20, 4u << 20), "");
    EXPECT_EQ(receive_buffer_shortfall(0, 212992), "");  // the profile asks for the system default
    EXPECT_EQ(receive_buffer_shortfall(4u << 20, 0), "");  // cap unknown
    const auto f = std::filesystem::temp_directory_path() / ("gdnav_rmem_" + std::to_string(getpid()));
    std::ofstream(f) << "212992\n";
    EXPECT_EQ(kernel_receive_buffer_cap(f), 212992u);
    std::filesystem::remove(f);
    EXPECT_EQ(kernel_receive_buffer_cap(f), 0u);
}

// Every shipped profile's participant lease outlasts the longest member timeout: a participant silent for less than
// run.member_timeout_s (a starved or paused process) must not be dropped by its peers' DDS, which unmatches its
// endpoints and loses what was written meanwhile (docs/runtime.md, "Participant lease").
TEST(DdsProfile, TheParticipantLeaseOutlastsTheLongestMemberTimeout) {
    for (const char* name : {"gdnav_profiles.xml", "shm_profiles.xml", "lossy_link.xml", "two_hosts_udp.xml"}) {
        SCOPED_TRACE(name);
        DdsContext dds(200 + static_cast<int>(getpid() % 30), config_dir() / "dds" / name,
                       std::string("gdnav.test.lease.") + name);
        const auto& d = dds.participant()->get_qos().wire_protocol().builtin.discovery_config;
        const double lease_s = d.leaseDuration.seconds + 1e-9 * d.leaseDuration.nanosec;
        const double announce_s = d.leaseDuration_announcementperiod.seconds +
                                  1e-9 * d.leaseDuration_announcementperiod.nanosec;
        EXPECT_GT(lease_s, gdnav::framework::kMemberTimeoutMax_s + 2.0 * announce_s) << lease_s << " s";
    }
}

TEST(DdsProfile, AWriterProfileTheFileDoesNotDefineFallsBackToTheOneGiven) {
    // The members' StepDone and status writers ask for gdnav_member_control_writer with gdnav_control_writer as the
    // fallback, so a profile file of a user's that predates it (or lossy_link.xml, which leaves it out) still works.
    // Tested with a name no file defines: one process keeps the first file's profiles for every later file.
    DdsContext dds(200 + static_cast<int>(getpid() % 30), config_dir() / "dds" / "gdnav_profiles.xml",
                   "gdnav.test.fallback");
    DataWriter* w = dds.writer("gdnav_test/fallback", message_ops<gdnav::msg::StepDone>(), "gdnav_no_such_profile",
                               kControlWriterProfile);
    ASSERT_NE(w, nullptr);
    const auto& hb = w->get_qos().reliable_writer_qos().times.heartbeatPeriod;
    EXPECT_EQ(hb.seconds, 0);
    EXPECT_EQ(hb.nanosec, 100'000'000u);  // gdnav_control_writer's
    EXPECT_EQ(w->get_qos().history().depth, 256);
    EXPECT_THROW(dds.writer("gdnav_test/no_fallback", message_ops<gdnav::msg::StepDone>(), "gdnav_no_such_profile"),
                 std::runtime_error);
}
