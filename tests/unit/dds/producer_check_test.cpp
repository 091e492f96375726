// Whose samples an input uses (dds/participants.hpp, dds/host/producer_check.hpp) and the rate limit of per-sample
// warnings (dds/host/warn_limit.hpp): the announcement's encoding, the decisions for announced, unannounced and
// unknown participants, and, over DDS, that a participant learns what another one announced.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "dds/dds_context.hpp"
#include "dds/host/producer_check.hpp"
#include "dds/host/warn_limit.hpp"
#include "framework/run_config.hpp"

using namespace gdnav::framework;
using namespace gdnav::dds;

namespace {

GuidPrefix prefix(unsigned char n) {
    GuidPrefix p;
    p.value[11] = n;
    return p;
}

}  // namespace

TEST(Participants, AnAnnouncementNamesItsMembersAndNothingElseIsOne) {
    const auto bytes = announcement({"nav_air", "nav_att"});
    EXPECT_EQ(std::string(bytes.begin(), bytes.end()), "gdnav-members=nav_air,nav_att");
    EXPECT_EQ(announced_members(bytes), (MemberNames{"nav_air", "nav_att"}));
    EXPECT_TRUE(announcement({}).empty());
    for (const std::string other : {"", "gdnav-members=", "members=nav_air", "GDNAV-MEMBERS=nav_air", "x"})
        EXPECT_FALSE(announced_members({other.begin(), other.end()})) << other;
}

TEST(ProducerCheck, AnAnnouncedProducerIsAcceptedAndEveryoneElseIsNot) {
    Participants known;
    known.add(prefix(1), MemberNames{"sensors_air"});
    known.add(prefix(2), MemberNames{"nav_air", "sensors_gnss"});  // another gdnav process
    known.add(prefix(3), std::nullopt);                              // a plain participant (a tool, another vendor)
    host::ProducerCheck check;
    EXPECT_FALSE(check.configured());
    check.configure({"sensors_air"}, {true}, &known);
    EXPECT_TRUE(check.accepts(prefix(1)));
    EXPECT_FALSE(check.accepts(prefix(2)));
    EXPECT_FALSE(check.accepts(prefix(3)));
    EXPECT_FALSE(check.accepts(prefix(4)));  // not (yet) discovered
    EXPECT_TRUE(check.accepts(prefix(1)));   // cached, same answer
}

TEST(ProducerCheck, AStartedProducerIsNeverTakenForAPlainParticipantEvenBeforeItIsDiscovered) {
    Participants known;
    known.add(prefix(3), std::nullopt);
    host::ProducerCheck check;
    check.configure({"sensors_air"}, {true}, &known);
    EXPECT_FALSE(check.accepts(prefix(3)));
    known.add(prefix(1), MemberNames{"sensors_air"});  // discovered later: the cache is dropped
    EXPECT_TRUE(check.accepts(prefix(1)));
    EXPECT_FALSE(check.accepts(prefix(3)));
}

TEST(ProducerCheck, AnExternalProducerThatNobodyAnnouncesMayBeAPlainParticipant) {
    Participants known;
    known.add(prefix(3), std::nullopt);  // e.g. a Cyclone DDS member
    host::ProducerCheck check;
    check.configure({"chain_controller"}, {false}, &known);
    EXPECT_TRUE(check.accepts(prefix(3)));
    // Once a gdnav participant announces it (the C++ or Python client library), only that one is its producer.
    known.add(prefix(5), MemberNames{"chain_controller"});
    EXPECT_TRUE(check.accepts(prefix(5)));
    EXPECT_FALSE(check.accepts(prefix(3)));
    EXPECT_EQ(check.names(), "chain_controller");
}

TEST(ProducerCheck, ATopicWithTwoProducersAcceptsBoth) {
    Participants known;
    known.add(prefix(1), MemberNames{"a"});
    known.add(prefix(2), MemberNames{"b", "c"});
    known.add(prefix(3), MemberNames{"d"});
    host::ProducerCheck check;
    check.configure({"a", "c"}, {true, true}, &known);
    EXPECT_TRUE(check.accepts(prefix(1)));
    EXPECT_TRUE(check.accepts(prefix(2)));
    EXPECT_FALSE(check.accepts(prefix(3)));
    EXPECT_EQ(check.names(), "a, c");
}

TEST(WarnLimit, TheFirstOccurrenceIsLoggedThenOneCountedLinePerPeriod) {
    host::WarnLimit w;
    EXPECT_EQ(w.occur(100.0), 1u);  // the first: logged at once
    EXPECT_EQ(w.occur(100.1), 0u);
    EXPECT_EQ(w.occur(104.9), 0u);
    EXPECT_EQ(w.occur(105.0), 3u);  // one period after the last line: it stands for the three since then
    EXPECT_EQ(w.occur(109.0), 0u);
    EXPECT_EQ(w.occur(200.0), 2u);
    EXPECT_EQ(w.total(), 6u);
}

TEST(Participants, AParticipantLearnsOverDdsWhichMembersAnotherOneHosts) {
    const int domain = 192 + static_cast<int>(getpid() % 20);
    const auto profile = config_dir() / "dds" / "gdnav_profiles.xml";
    DdsContext host_side(domain, profile, "gdnav.test.host", {}, {}, {"test_producer_a", "test_producer_b"});
    DdsContext plain(domain, profile, "gdnav.test.plain");
    DdsContext reader_side(domain, profile, "gdnav.test.reader");
    const GuidPrefix host_p = host_side.participant()->guid().guidPrefix;
    const GuidPrefix plain_p = plain.participant()->guid().guidPrefix;
    EXPECT_EQ(host_side.participants().members_of(host_p), (MemberNames{"test_producer_a", "test_producer_b"}));
    bool seen = false;
    for (int i = 0; i < 200 && !seen; ++i) {  // discovery: at most 10 s
        seen = reader_side.participants().knows(host_p) && reader_side.participants().knows(plain_p);
        if (!seen) std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ASSERT_TRUE(seen);
    EXPECT_EQ(reader_side.participants().members_of(host_p), (MemberNames{"test_producer_a", "test_producer_b"}));
    EXPECT_FALSE(reader_side.participants().members_of(plain_p));  // known, and announced nothing
    EXPECT_TRUE(reader_side.participants().announces("test_producer_b"));
    EXPECT_FALSE(reader_side.participants().announces("test_producer_c"));
}
