// Who reads a decimated mirror (dds/host/mirror.hpp): the rule an observer applies to each input once the member
// table names its producers. Over DDS: tests/integration/mirror_test.cpp.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "framework/component.hpp"
#include "framework/stride_policy.hpp"
#include "dds/host/mirror.hpp"

namespace framework = gdnav::framework;

TEST(Mirror, TopicNameCarriesTheStride) {
    EXPECT_EQ(gdnav::dds::kMirrorStride, 10u);
    // A decimation that is a multiple of 10 (the live view's default 10, or 20, 100, 1000) reads at stride 10
    // (effective_stride takes the largest divisor up to kMaxStride; StrideFilter tests), which the mirror serves.
    EXPECT_EQ(framework::kMaxStride, gdnav::dds::kMirrorStride);
    EXPECT_EQ(gdnav::dds::mirror_topic("gdnav/Truth"), "gdnav/Truth/every_10_steps");
    EXPECT_EQ(gdnav::dds::mirror_topic("chain/state"), "chain/state/every_10_steps");
}

TEST(Mirror, AnObserverReadsItOnlyWhenEveryProducerWritesOneAndItsStrideIsAMultiple) {
    const std::set<std::string> gdnav_elsewhere{"flight_physics", "nav_pos"};
    const auto writes = [&](const std::string& n) { return gdnav_elsewhere.count(n) > 0; };
    EXPECT_TRUE(gdnav::dds::reads_mirror(10, false, {"flight_physics"}, writes));
    EXPECT_TRUE(gdnav::dds::reads_mirror(10, false, {"flight_physics", "nav_pos"}, writes));
    // An external member (or one in the observer's own process) among the producers: the topic itself.
    EXPECT_FALSE(gdnav::dds::reads_mirror(10, false, {"flight_physics", "my_filter"}, writes));
    EXPECT_FALSE(gdnav::dds::reads_mirror(10, false, {"my_filter"}, writes));
    // Nobody produces it: the topic itself (the input is treated as lost anyway).
    EXPECT_FALSE(gdnav::dds::reads_mirror(10, false, {}, writes));
    // Strides the mirror cannot serve, and no stride at all.
    for (std::uint64_t s : {0u, 1u, 4u, 5u, 8u, 9u})
        EXPECT_FALSE(gdnav::dds::reads_mirror(s, false, {"nav_pos"}, writes)) << s;
    EXPECT_TRUE(gdnav::dds::reads_mirror(20, false, {"nav_pos"}, writes));
    // A secure run has no mirrors.
    EXPECT_FALSE(gdnav::dds::reads_mirror(10, true, {"nav_pos"}, writes));
}
