// The stride filter's reading of SampleStamp.step from a serialised sample (runtime/stride_filter.hpp): the same
// bytes the writer's Fast DDS hands it, i.e. what MessageOps::serialize writes (CDR with its encapsulation header).
#include <gtest/gtest.h>

#include <vector>

#include "runtime/messages.hpp"
#include "runtime/stride_filter.hpp"
#include "runtime/topic_types.hpp"

namespace rt = gdnav::runtime;

TEST(StrideFilter, ReadsTheStepOfEveryDataTopicFromItsCdrBytes) {
    rt::register_gdnav_topics();
    for (const std::string& topic : rt::known_topics()) {
        const rt::MessageOps* ops = rt::find_topic(topic);
        ASSERT_NE(ops, nullptr) << topic;
        void* sample = ops->create();
        ops->set_stamp(sample, 7, 123456789012ULL, 42.5);
        std::vector<std::uint8_t> cdr;
        ops->serialize(sample, cdr);
        ops->destroy(sample);
        std::uint64_t step = 0;
        ASSERT_TRUE(rt::stamp_step_of_cdr(cdr.data(), static_cast<std::uint32_t>(cdr.size()), step)) << topic;
        EXPECT_EQ(step, 123456789012ULL) << topic;
    }
}

TEST(StrideFilter, ReadsBigEndianAndRefusesShortPayloads) {
    // Encapsulation CDR_BE (0x0000), run_id = 1, step = 0x0102030405060708, both big-endian.
    std::vector<std::uint8_t> be{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 2, 3, 4, 5, 6, 7, 8};
    std::uint64_t step = 0;
    ASSERT_TRUE(rt::stamp_step_of_cdr(be.data(), static_cast<std::uint32_t>(be.size()), step));
    EXPECT_EQ(step, 0x0102030405060708ULL);
    be[1] = 1;  // CDR_LE: the same eight bytes read the other way round
    ASSERT_TRUE(rt::stamp_step_of_cdr(be.data(), static_cast<std::uint32_t>(be.size()), step));
    EXPECT_EQ(step, 0x0807060504030201ULL);
    EXPECT_FALSE(rt::stamp_step_of_cdr(be.data(), 19, step));
    EXPECT_FALSE(rt::stamp_step_of_cdr(nullptr, 0, step));
}
