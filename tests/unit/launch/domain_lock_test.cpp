// DDS domains of this host's runs (launch/domain_lock.hpp): a domain held by a run is never handed to another, the
// lowest free one is, and a released domain is free again. Locks in a folder of the test's own.
#include "launch/domain_lock.hpp"

#include <gtest/gtest.h>
#include <stdlib.h>

#include "temp_dir.hpp"

using gdnav::launch::DomainLock;

TEST(DomainLock, AHeldDomainIsSkippedAndFreeAgainOnceReleased) {
    const gdnav::test::TempDir dir;
    ASSERT_EQ(setenv("GDNAV_DOMAIN_LOCKS", dir.path().c_str(), 1), 0);
    DomainLock a, b, c;
    EXPECT_EQ(a.lock_free_domain(), DomainLock::kFirstAutoDomain);
    // flock locks belong to the open file: a second lock of the same file fails even inside one process.
    EXPECT_FALSE(b.try_lock(DomainLock::kFirstAutoDomain));
    EXPECT_EQ(b.lock_free_domain(), DomainLock::kFirstAutoDomain + 1);
    EXPECT_TRUE(c.try_lock(DomainLock::kFirstAutoDomain + 5));  // a run with --domain
    a.release();
    EXPECT_EQ(a.lock_free_domain(), DomainLock::kFirstAutoDomain);
    EXPECT_FALSE(a.try_lock(DomainLock::kFirstAutoDomain + 5));
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "25.lock"));
    unsetenv("GDNAV_DOMAIN_LOCKS");
}
