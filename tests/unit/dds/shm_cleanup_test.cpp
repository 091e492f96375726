// The shared-memory cleanup's name filter: only Fast DDS segment and semaphore names are removal candidates.
#include <gtest/gtest.h>

#include "launch/shm_cleanup.hpp"

using namespace gdnav::launch;

TEST(Shm, OnlyFastDdsNamesAreCandidates) {
    EXPECT_TRUE(is_fastdds_shm_name("fastrtps_0a1b2c3d4e5f6a7b"));
    EXPECT_TRUE(is_fastdds_shm_name("sem.fastrtps_port7413_mutex"));
    EXPECT_TRUE(is_fastdds_shm_name("fast_datasharing_01.0f.aa.bb"));
    EXPECT_FALSE(is_fastdds_shm_name("postgres_shm"));
    EXPECT_FALSE(is_fastdds_shm_name("sem.other"));
}
