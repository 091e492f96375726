// An input with a stride (InputBase::stride, dds/filters/stride_filter.hpp) over real DDS: a reader outside the run asks
// for every 10th step of ImuSample during a distributed run and must get exactly those steps, all of them — the
// producer's writer filters them (gdnav participants register the filter), and nothing it needs goes missing.
// What the filter saves on the wire is measured, not tested (docs/runtime.md, "Next cut"; docs/viewing.md).
#include <gtest/gtest.h>
#include <unistd.h>

#include <vector>

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

TEST(StrideReader, ADistributedRunSendsAStridedReaderExactlyItsSteps) {
    constexpr int kDomain = 148;  // integration tests run one at a time (RUN_SERIAL)
    constexpr std::uint64_t kSteps = 2000, kStride = 10;
    framework::register_gdnav_topics();
    const msg::MessageOps* ops = framework::find_topic(gdnav::topics::kImu);
    ASSERT_NE(ops, nullptr);
    gdnav::dds::DdsContext dds(kDomain, framework::config_dir() / "dds" / "gdnav_profiles.xml", "gdnav.test.strided");
    DataReader* reader = dds.reader(gdnav::topics::kImu, *ops, gdnav::dds::kDataReaderProfile, kStride);

    const auto out = temp_dir("stride-reader");
    const pid_t launcher = start({GDNAV_GDNAV_EXE, "run", "--scenario", "default", "--layout", "distributed", "--steps",
                                  std::to_string(kSteps), "--domain", std::to_string(kDomain), "--out", out.string()},
                                 out.string() + ".log");
    std::vector<std::uint64_t> steps;
    const int code = read_while_running(launcher, *reader, *ops, 180.0, [&](std::uint64_t s) { steps.push_back(s); });
    std::printf("strided reader (every %llu steps): %zu ImuSample samples of a %llu-step distributed run, first %llu, "
                "last %llu\n", static_cast<unsigned long long>(kStride), steps.size(),
                static_cast<unsigned long long>(kSteps), static_cast<unsigned long long>(steps.empty() ? 0 : steps.front()),
                static_cast<unsigned long long>(steps.empty() ? 0 : steps.back()));
    ASSERT_EQ(code, 0) << read_file(out.string() + ".log");
    ASSERT_FALSE(steps.empty());
    // It matched during the start-up, before step 0 (members wait for each other, not for it): every multiple of 10
    // from its first sample on, in order, and nothing else.
    for (std::size_t i = 0; i < steps.size(); ++i) {
        ASSERT_EQ(steps[i] % kStride, 0u) << "sample " << i << " is of step " << steps[i];
        if (i > 0) {
            ASSERT_EQ(steps[i], steps[i - 1] + kStride) << "a step is missing or repeated after " << steps[i - 1];
        }
    }
    EXPECT_EQ(steps.back(), kSteps - kStride);
}
