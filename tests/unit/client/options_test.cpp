// gdnav::client::Options::from_args: a member started by gdnav (run.members) reads the run's settings from its
// environment; flags given on the command line win; a malformed variable is one error naming it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "gdnav/client/member.hpp"

using gdnav::client::Options;

namespace {

// Sets the variables of a member started by gdnav for one test, and removes them after it.
class MemberEnvironment : public ::testing::Test {
protected:
    void SetUp() override {
        setenv("GDNAV_MEMBER", "nav_att_x", 1);
        setenv("GDNAV_DOMAIN", "163", 1);
        setenv("GDNAV_RUN", "7", 1);
        setenv("GDNAV_SECURITY", "/tmp/pki", 1);
        setenv("GDNAV_DDS_PROFILE", "/tmp/profile.xml", 1);
    }
    void TearDown() override {
        for (const char* v : {"GDNAV_MEMBER", "GDNAV_DOMAIN", "GDNAV_RUN", "GDNAV_SECURITY", "GDNAV_DDS_PROFILE"})
            unsetenv(v);
    }
    static Options parse(std::vector<const char*> argv) {
        argv.insert(argv.begin(), "member");
        return Options::from_args(static_cast<int>(argv.size()), argv.data(), "nav_att");
    }
};

}  // namespace

TEST_F(MemberEnvironment, WithoutFlagsTheEnvironmentGivesNameDomainRunSecurityAndProfile) {
    const Options o = parse({});
    EXPECT_EQ(o.name, "nav_att_x");
    EXPECT_EQ(o.domain_id, 163);
    EXPECT_EQ(o.run_id, 7u);
    EXPECT_EQ(o.security, "/tmp/pki");
    EXPECT_EQ(o.dds_profile, "/tmp/profile.xml");
}

TEST_F(MemberEnvironment, FlagsWinOverTheEnvironment) {
    const Options o =
        parse({"--name", "mine", "--domain", "5", "--run", "2", "--security", "/s", "--dds-profile", "/p"});
    EXPECT_EQ(o.name, "mine");
    EXPECT_EQ(o.domain_id, 5);
    EXPECT_EQ(o.run_id, 2u);
    EXPECT_EQ(o.security, "/s");
    EXPECT_EQ(o.dds_profile, "/p");
}

TEST_F(MemberEnvironment, AMalformedVariableIsOneErrorNamingIt) {
    setenv("GDNAV_DOMAIN", "233", 1);  // above Fast DDS's highest domain id of the default port mapping
    try {
        (void)parse({});
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("GDNAV_DOMAIN"), std::string::npos) << e.what();
    }
    setenv("GDNAV_DOMAIN", "163", 1);
    setenv("GDNAV_RUN", "x", 1);
    EXPECT_THROW((void)parse({}), std::invalid_argument);
}

TEST(MemberOptions, WithoutEnvironmentTheDefaultsStand) {
    for (const char* v : {"GDNAV_MEMBER", "GDNAV_DOMAIN", "GDNAV_RUN", "GDNAV_SECURITY", "GDNAV_DDS_PROFILE"})
        unsetenv(v);
    const char* argv[] = {"member"};
    const Options o = Options::from_args(1, argv, "nav_att");
    EXPECT_EQ(o.name, "nav_att");
    EXPECT_EQ(o.domain_id, 0);
    EXPECT_EQ(o.run_id, 0u);
    EXPECT_TRUE(o.security.empty());
    EXPECT_TRUE(o.dds_profile.empty());
}
