#include "launch/plan/plan_host.hpp"

#include <sys/stat.h>

#include <cstdlib>
#include <fstream>

#include <gtest/gtest.h>

#include "config/config.hpp"
#include "temp_dir.hpp"
#include "paper_scenarios.hpp"

namespace gdnav::launch::deploy {
namespace {

namespace fs = std::filesystem;

// Sets $PATH for the test's lifetime.
class ScopedPath {
public:
    explicit ScopedPath(const std::string& value) {
        if (const char* p = std::getenv("PATH")) old_ = p;
        setenv("PATH", value.c_str(), 1);
    }
    ~ScopedPath() { setenv("PATH", old_.c_str(), 1); }
    ScopedPath(const ScopedPath&) = delete;
    ScopedPath& operator=(const ScopedPath&) = delete;

private:
    std::string old_;
};

// The two-host plan of the repository (deploy/plans/two_hosts_netns.yaml) with `discovery` and `server` replaced.
fs::path write_plan(const fs::path& dir, const std::string& discovery_lines) {
    const fs::path f = dir / "plan.yaml";
    std::ofstream(f) << "scenario: paper2\nseed: 3\ndomain_id: 7\n" << discovery_lines
                     << "run:\n  startup_timeout_s: 60\nhosts:\n"
                        "  a:\n    address: 10.231.0.1\n    clock: true\n"
                        "    members: [flight_physics, sensors_inertial, sensors_magnetic, sensors_air, "
                        "sensors_atmospheric, sensors_gnss]\n"
                        "  b:\n    address: 10.231.0.2\n    process: distributed\n"
                        "    members: [nav_air, nav_att, nav_pos, guidance, control, nav_recorder, recorder]\n";
    return f;
}

class PlanHostTest : public ::testing::Test {
protected:
    void SetUp() override { scenario::register_paper_scenarios(); }

    PlanHostRun run_host(const fs::path& plan_file, const std::string& host) {
        const Plan plan = Plan::load(plan_file);
        PlanHostRequest req;
        req.host = host;
        req.out = dir_.path() / ("out_" + host);
        req.steps = 50;
        req.log_level = "warn";
        return plan_host_run(plan, req, framework::resolve_scenario("paper2"), reg_);
    }

    test::TempDir dir_;
    framework::ComponentRegistry reg_;  // no rewrite: no component is built
};

TEST_F(PlanHostTest, HostWithoutTheClockRunsItsMembersOfTheRun) {
    const PlanHostRun r = run_host(write_plan(dir_.path(), "discovery: peers\n"), "b");
    EXPECT_EQ(r.lo.layout, "distributed");
    EXPECT_EQ(r.lo.log_level, "warn");
    EXPECT_TRUE(r.lo.slice);
    EXPECT_FALSE(r.lo.start_clock);
    // `recorder` is placed on b but is not a member of the run without --record.
    EXPECT_EQ(r.lo.only, (std::vector<std::string>{"nav_air", "nav_att", "nav_pos", "guidance", "control",
                                                   "nav_recorder"}));
    EXPECT_TRUE(r.lo.services.empty());
    EXPECT_EQ(r.rc.domain_id, 7);
    EXPECT_EQ(r.rc.info.seed, 3u);
    EXPECT_EQ(r.rc.info.steps, 50u);
    EXPECT_EQ(r.rc.startup_timeout_s, 60.0);
    EXPECT_EQ(r.rc.out_dir, (dir_.path() / "out_b").string());
    EXPECT_EQ(r.rc.dds_profile, fs::absolute(dir_.path() / "out_b" / "dds_plan.xml"));
    EXPECT_TRUE(fs::exists(dir_.path() / "out_b" / "dds_plan.xml"));
    EXPECT_EQ(r.summary, "plan " + (dir_.path() / "plan.yaml").string() +
                             ": host b (10.231.0.2) runs nav_air,nav_att,nav_pos,guidance,control,nav_recorder as "
                             "distributed, discovery peers, DDS domain 7; other hosts: a (10.231.0.1): clock,"
                             "flight_physics,sensors_inertial,sensors_magnetic,sensors_air,sensors_atmospheric,"
                             "sensors_gnss");
}

TEST_F(PlanHostTest, EmptyHostNameIsTheClockHost) {
    const PlanHostRun r = run_host(write_plan(dir_.path(), "discovery: peers\n"), "");
    EXPECT_TRUE(r.lo.start_clock);
    EXPECT_EQ(r.lo.layout, "composed");
    EXPECT_EQ(r.lo.only.size(), 6u);
}

TEST_F(PlanHostTest, DiscoveryServerIsTheProgramFoundOnPath) {
    const fs::path bin = dir_.path() / "bin";
    fs::create_directories(bin);
    std::ofstream(bin / kDiscoveryServerProgram) << "#!/bin/sh\n";
    chmod((bin / kDiscoveryServerProgram).c_str(), 0755);
    ScopedPath path("/nonexistent:" + bin.string());
    const PlanHostRun r = run_host(write_plan(dir_.path(), "discovery: server\nserver: {host: a, port: 11900}\n"), "a");
    ASSERT_EQ(r.lo.services.size(), 1u);
    EXPECT_EQ(r.lo.services[0].first, "discovery server 0");
    EXPECT_EQ(r.lo.services[0].second, (std::vector<std::string>{(bin / kDiscoveryServerProgram).string(), "-i", "0",
                                                                  "-l", "10.231.0.1", "-p", "11900"}));
}

TEST_F(PlanHostTest, MissingDiscoveryServerProgramIsOneLineNamingIt) {
    ScopedPath path((dir_.path() / "empty").string());
    try {
        (void)run_host(write_plan(dir_.path(), "discovery: server\nserver: {host: a}\n"), "a");
        FAIL() << "no error";
    } catch (const config::ConfigError& e) {
        EXPECT_EQ(std::string(e.what()), "config error: fast-discovery-server not found on PATH (the plan's discovery "
                                         "server; Debian: apt-get install fastdds-tools)");
    }
}

TEST_F(PlanHostTest, UnknownHostNamesThePlanAndTheKey) {
    const fs::path plan = write_plan(dir_.path(), "discovery: peers\n");
    try {
        (void)run_host(plan, "c");
        FAIL() << "no error";
    } catch (const config::ConfigError& e) {
        EXPECT_EQ(std::string(e.what()), "config error: " + plan.string() + ": key 'hosts': no host 'c' (hosts: a, b)");
    }
}

TEST_F(PlanHostTest, MemberOnNoHostIsAnError) {
    const fs::path f = dir_.path() / "plan.yaml";
    std::ofstream(f) << "scenario: paper2\ndomain_id: 7\ndiscovery: peers\nhosts:\n"
                        "  a: {address: 10.231.0.1, clock: true, members: [flight_physics]}\n";
    EXPECT_THROW((void)run_host(f, "a"), config::ConfigError);
}

}  // namespace
}  // namespace gdnav::launch::deploy
