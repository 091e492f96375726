// Issue 13 item 1: in the composed layout the members of one process hand samples to each other in process
// (dds/host/host_inbox.hpp), and a topic is published on DDS only while a reader outside the process is matched.
// This test is such an outside reader (a monitoring tool that is not a member of the run): it must see the
// composed run's ImuSample topic on DDS, step after step up to the last one, from the step at which the run's process
// has matched it on (samples before the match are handed over in process only). The run is paced at 10x real time
// (3 s) so that the match, which on a loaded machine took longer than a run at full speed, happens during the run. Its
// reader keeps the whole run (outside_reader.hpp: with the profile's 72 samples a loaded machine cost it 46 steps).
// (That the in-process hand-over gives the same results as the other layouts is the Layouts, Flight and
// ScheduledFaults tests' bit-identity check.)
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>

#include "outside_reader.hpp"
#include "process_util.hpp"
#include "dds/dds_context.hpp"
#include "msgs/messages.hpp"
#include "framework/run_config.hpp"
#include "framework/topic_types.hpp"

using namespace gdnav::testing;
namespace msg = gdnav::msg;
namespace framework = gdnav::framework;
using namespace eprosima::fastdds::dds;

TEST(ComposedVisibility, AReaderOutsideTheProcessSeesEveryStepOfALocallyHandedTopic) {
    constexpr int kDomain = 149;  // integration tests run one at a time (RUN_SERIAL)
    constexpr std::uint64_t kSteps = 3000;
    framework::register_gdnav_topics();
    const msg::MessageOps* ops = framework::find_topic(gdnav::topics::kImu);
    ASSERT_NE(ops, nullptr);
    gdnav::dds::DdsContext dds(kDomain, framework::config_dir() / "dds" / "gdnav_profiles.xml", "gdnav.test.monitor");
    DataReader* reader = whole_run_reader(dds, gdnav::topics::kImu, *ops, static_cast<std::int32_t>(kSteps) + 16);
    ASSERT_NE(reader, nullptr);

    const auto out = temp_dir("composed-monitor");
    const pid_t launcher = start({GDNAV_GDNAV_EXE, "run", "--scenario", "default", "--layout", "composed", "--steps",
                                  std::to_string(kSteps), "--realtime", "10", "--domain", std::to_string(kDomain),
                                  "--out", out.string()},
                                 out.string() + ".log");
    std::uint64_t received = 0, first = UINT64_MAX, last = 0;
    bool increasing = true;
    const int code = read_while_running(launcher, *reader, *ops, 120.0, [&](std::uint64_t s) {
        if (received > 0 && s <= last) increasing = false;
        first = std::min(first, s);
        last = s;
        ++received;
    });
    std::printf("outside reader: %llu ImuSample samples, steps %llu..%llu of a %llu-step composed run\n",
                static_cast<unsigned long long>(received), static_cast<unsigned long long>(first),
                static_cast<unsigned long long>(last), static_cast<unsigned long long>(kSteps));
    ASSERT_EQ(code, 0) << read_file(out.string() + ".log");
    EXPECT_GT(received, 0u);
    EXPECT_TRUE(increasing);
    EXPECT_EQ(last, kSteps - 1);
    EXPECT_EQ(received, last - first + 1);  // none missing once matched
}
