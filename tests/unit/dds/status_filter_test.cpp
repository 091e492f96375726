// The status filter (dds/filters/status_filter.hpp): its reading of ComponentStatus.member from the CDR bytes the
// writer's Fast DDS hands it, and a filtered status reader over real DDS (two participants in this process) that
// gets the chosen member's statuses and nothing else.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "dds/dds_context.hpp"
#include "framework/lockstep.hpp"
#include "msgs/message_ops.hpp"
#include "msgs/messages.hpp"
#include "framework/run_config.hpp"
#include "dds/filters/status_filter.hpp"

namespace framework = gdnav::framework;
namespace msg = gdnav::msg;
using namespace eprosima::fastdds::dds;

namespace {
std::vector<std::uint8_t> status_cdr(const std::string& member) {
    msg::ComponentStatus s;
    s.run_id(3);
    s.step(1234);
    s.t_s(12.34);
    s.member(member);
    s.host("h:1");
    s.message("some text after the name");
    std::vector<std::uint8_t> cdr;
    msg::message_ops<msg::ComponentStatus>().serialize(&s, cdr);
    return cdr;
}
}  // namespace

TEST(StatusFilter, ReadsTheMemberNameOfASerialisedStatus) {
    for (const std::string& name : std::vector<std::string>{"clock", "nav_att", "a", std::string(63, 'm')}) {
        const auto cdr = status_cdr(name);
        std::string_view m;
        ASSERT_TRUE(gdnav::dds::status_member_of_cdr(cdr.data(), static_cast<std::uint32_t>(cdr.size()), m)) << name;
        EXPECT_EQ(m, name);
    }
    const auto cdr = status_cdr("nav_pos");
    std::string_view m;
    EXPECT_FALSE(gdnav::dds::status_member_of_cdr(cdr.data(), 4 + 24 + 4 + 3, m));  // name cut short
    EXPECT_FALSE(gdnav::dds::status_member_of_cdr(cdr.data(), 20, m));
    EXPECT_FALSE(gdnav::dds::status_member_of_cdr(nullptr, 0, m));
}

TEST(StatusFilter, AFilteredStatusReaderGetsOnlyItsMemberOverDds) {
    // Another run may share the domain: this test's statuses carry a run id of their own and only those count.
    const int domain = 152 + static_cast<int>(getpid() % 40);
    const std::uint64_t run_id = 1000000 + static_cast<std::uint64_t>(getpid());
    const auto profile = framework::config_dir() / "dds" / "gdnav_profiles.xml";
    gdnav::dds::DdsContext writer_side(domain, profile, "gdnav.test.status_writer");
    gdnav::dds::DdsContext reader_side(domain, profile, "gdnav.test.status_reader");
    const auto& ops = msg::message_ops<msg::ComponentStatus>();
    DataWriter* w = writer_side.writer(gdnav::topics::kStatus, ops, gdnav::dds::kControlWriterProfile);
    DataReader* only_clock =
        reader_side.status_reader(gdnav::topics::kStatus, ops, gdnav::dds::kControlReaderProfile, "clock");
    DataReader* all = reader_side.reader(gdnav::topics::kStatus, ops, gdnav::dds::kControlReaderProfile);
    for (int i = 0; i < 200; ++i) {  // wait for both matches (at most 10 s)
        PublicationMatchedStatus st;
        w->get_publication_matched_status(st);
        if (st.current_count == 2) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    const std::vector<std::string> sent{"nav_att", "clock", "clockwork", "sensors_gnss", "clock", "cloc"};
    msg::ComponentStatus s;
    s.run_id(run_id);
    for (std::size_t i = 0; i < sent.size(); ++i) {
        s.step(i);
        s.member(sent[i]);
        ASSERT_TRUE(w->write(&s));
    }
    auto take = [&](DataReader* r, std::size_t want) {
        std::vector<std::string> got;
        SampleInfo info;
        for (int i = 0; i < 200; ++i) {  // at least one pass, at most 4 s
            msg::ComponentStatus in;
            while (r->take_next_sample(&in, &info) == ReturnCode_t::RETCODE_OK)
                if (info.valid_data && in.run_id() == run_id)
                    got.push_back(in.member().to_string() + "@" + std::to_string(in.step()));
            if (got.size() >= want) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        return got;
    };
    EXPECT_EQ(take(all, sent.size()).size(), sent.size());
    const auto clock_only = take(only_clock, 2);
    EXPECT_EQ(clock_only, (std::vector<std::string>{"clock@1", "clock@4"}));
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // nothing else arrives later
    EXPECT_TRUE(take(only_clock, 0).empty());
}
