// The stride filter's reading of SampleStamp.step from a serialised sample (dds/filters/stride_filter.hpp): the same
// bytes the writer's Fast DDS hands it, i.e. what MessageOps::serialize writes (CDR with its encapsulation header).
#include <gtest/gtest.h>

#include <vector>

#include "framework/component.hpp"
#include "msgs/messages.hpp"
#include "dds/filters/stride_filter.hpp"
#include "framework/stride_policy.hpp"
#include "framework/topic_types.hpp"

namespace msg = gdnav::msg;
namespace framework = gdnav::framework;

TEST(StrideFilter, ReadsTheStepOfEveryDataTopicFromItsCdrBytes) {
    framework::register_gdnav_topics();
    for (const std::string& topic : framework::known_topics()) {
        const msg::MessageOps* ops = framework::find_topic(topic);
        ASSERT_NE(ops, nullptr) << topic;
        void* sample = ops->create();
        ops->set_stamp(sample, 7, 123456789012ULL, 42.5);
        std::vector<std::uint8_t> cdr;
        ops->serialize(sample, cdr);
        ops->destroy(sample);
        std::uint64_t step = 0;
        ASSERT_TRUE(gdnav::dds::stamp_step_of_cdr(cdr.data(), static_cast<std::uint32_t>(cdr.size()), step)) << topic;
        EXPECT_EQ(step, 123456789012ULL) << topic;
    }
}

TEST(StrideFilter, ReadsBigEndianAndRefusesShortPayloads) {
    // Encapsulation CDR_BE (0x0000), run_id = 1, step = 0x0102030405060708, both big-endian.
    std::vector<std::uint8_t> be{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 2, 3, 4, 5, 6, 7, 8};
    std::uint64_t step = 0;
    ASSERT_TRUE(gdnav::dds::stamp_step_of_cdr(be.data(), static_cast<std::uint32_t>(be.size()), step));
    EXPECT_EQ(step, 0x0102030405060708ULL);
    be[1] = 1;  // CDR_LE: the same eight bytes read the other way round
    ASSERT_TRUE(gdnav::dds::stamp_step_of_cdr(be.data(), static_cast<std::uint32_t>(be.size()), step));
    EXPECT_EQ(step, 0x0807060504030201ULL);
    EXPECT_FALSE(gdnav::dds::stamp_step_of_cdr(be.data(), 19, step));
    EXPECT_FALSE(gdnav::dds::stamp_step_of_cdr(nullptr, 0, step));
}

namespace {
struct Sink final : framework::Component {
    Sink() : Component("sink") {}
    void configure(const gdnav::config::Config&, const framework::RunInfo&, gdnav::rnd::Stream&) override {}
    void step(const framework::StepContext&) override {}
};
}  // namespace

TEST(StrideFilter, AnInputTakesTheLargestDivisorOfItsDecimationWithinTheBounds) {
    framework::register_gdnav_topics();
    Sink owner;
    framework::InputBase in(owner, gdnav::topics::kImu, framework::Lag::Same,
                            *framework::find_topic(gdnav::topics::kImu));
    const std::vector<std::pair<std::uint64_t, std::uint64_t>> cases{
        {0, 1}, {1, 1}, {2, 1}, {3, 1}, {4, 4}, {10, 10}, {12, 6}, {32, 8}, {64, 8}, {100, 10}, {1000, 10},
        {37, 1}, {74, 1}, {22, 1}};
    for (const auto& [n, want] : cases) {
        in.set_stride(n);
        EXPECT_EQ(framework::stride_of(in), want) << "decimation " << n;
        EXPECT_LE(framework::stride_of(in), framework::kMaxStride);
        EXPECT_TRUE(framework::stride_of(in) == 1 || framework::stride_of(in) >= framework::kMinStride);
        if (n > 0) {
            EXPECT_EQ(n % framework::stride_of(in), 0u) << "the steps it uses are among those it receives";
        }
    }
    in.set_stride(10);
    EXPECT_TRUE(framework::on_stride(in, 0));
    EXPECT_TRUE(framework::on_stride(in, 120));
    EXPECT_FALSE(framework::on_stride(in, 125));
}
