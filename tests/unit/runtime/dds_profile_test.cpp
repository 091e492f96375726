// The default DDS profile (config/dds/gdnav_profiles.xml) as Fast DDS actually loads it: UDPv4 only, no shared memory
// and no data sharing between processes (a SIGKILLed process must not be able to abort a healthy one through a
// shared-memory mutex, docs/runtime.md "Transports"), and the writers keep Fast DDS's default heartbeat period (a
// short one made long runs stall). Guards against an edit of the XML silently bringing either back.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>

#include "runtime/dds_context.hpp"
#include "runtime/messages.hpp"
#include "runtime/run_config.hpp"

using namespace gdnav::runtime;
using namespace eprosima::fastdds::dds;

TEST(DdsProfile, DefaultProfileUsesUdpOnlyWithoutSharedMemory) {
    const auto file = config_dir() / "dds" / "gdnav_profiles.xml";
    DdsContext dds(200 + static_cast<int>(getpid() % 30), file, "gdnav.test.profile");
    const DomainParticipantQos pq = dds.participant()->get_qos();
    EXPECT_FALSE(pq.transport().use_builtin_transports);
    ASSERT_FALSE(pq.transport().user_transports.empty());
    for (const auto& t : pq.transport().user_transports)
        EXPECT_NE(dynamic_cast<eprosima::fastdds::rtps::UDPv4TransportDescriptor*>(t.get()), nullptr);

    for (const char* profile : {kDataWriterProfile, kControlWriterProfile, kLatchedWriterProfile}) {
        SCOPED_TRACE(profile);
        DataWriter* w = dds.writer(std::string("gdnav_test/") + profile, message_ops<gdnav::msg::Tick>(), profile);
        EXPECT_EQ(w->get_qos().data_sharing().kind(), DataSharingKind::OFF);
        EXPECT_EQ(w->get_qos().reliability().kind, RELIABLE_RELIABILITY_QOS);
        EXPECT_EQ(w->get_qos().reliable_writer_qos().times.heartbeatPeriod.seconds, 3);
    }
    for (const char* profile : {kDataReaderProfile, kControlReaderProfile, kLatchedReaderProfile}) {
        SCOPED_TRACE(profile);
        DataReader* r = dds.reader(std::string("gdnav_test_r/") + profile, message_ops<gdnav::msg::Tick>(), profile);
        EXPECT_EQ(r->get_qos().data_sharing().kind(), DataSharingKind::OFF);
    }
}
