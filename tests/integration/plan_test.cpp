// Issue 12 items 1-3: deployment plans (gdnav run --plan on the clock's host, gdnav host --plan --name on the
// other), in two network namespaces joined by a veth pair: paper scenario #2 with physics and sensors on host a and
// the filters, guidance, control and recorders on host b records exactly what the single-host run records, with
// initial peers, through a Fast DDS discovery server, and over a link degraded by tc netem. Bad plans are one
// error each. The namespace tests need root (skipped otherwise).
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <thread>

#include <yaml-cpp/yaml.h>

#include "netns.hpp"
#include "process_util.hpp"
#include "runtime/lockstep.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

constexpr const char* kSteps = "2000";
constexpr const char* kRecord = "AirDataEstimate,AttitudeEstimate,PositionEstimate,ControlCommands,Truth";

std::string plan_file() { return std::string(GDNAV_SOURCE_DIR) + "/deploy/plans/two_hosts_netns.yaml"; }

// The plan of deploy/plans/two_hosts_netns.yaml with `edit` applied, written to a temporary file.
fs::path plan_with(const std::function<void(YAML::Node&)>& edit, const std::string& tag) {
    YAML::Node p = YAML::LoadFile(plan_file());
    edit(p);
    const fs::path f = temp_dir(tag) / "plan.yaml";
    std::ofstream(f) << p;
    return f;
}

struct PlanRun {
    int a{-1}, b{-1};
    std::map<std::string, std::string> digests;  // host b's recorder
    double steps_per_s{0.0};
    std::string logs;
};

PlanRun run_plan(const Namespaces& ns, const fs::path& plan, const std::string& tag) {
    const auto out = temp_dir(tag);
    const pid_t a = start(Namespaces::in(ns.a(), {GDNAV_GDNAV_EXE, "run", "--plan", plan.string(), "--steps", kSteps,
                                                 "--record", kRecord, "--out", (out / "a").string()}),
                          out / "a.log");
    const pid_t b = start(Namespaces::in(ns.b(), {GDNAV_GDNAV_EXE, "host", "--plan", plan.string(), "--name", "b",
                                                 "--steps", kSteps, "--record", kRecord, "--out",
                                                 (out / "b").string()}),
                          out / "b.log");
    PlanRun r;
    r.a = wait_for(a, 240.0);
    r.b = wait_for(b, 30.0);
    r.logs = read_file(out / "a.log") + read_file(out / "b.log");
    r.digests = read_digests(out / "b");
    if (fs::exists(out / "a" / "clock_summary.yaml"))
        r.steps_per_s = YAML::LoadFile((out / "a" / "clock_summary.yaml").string())["steps_per_s"].as<double>();
    return r;
}

}  // namespace

TEST(Plan, BadPlansAreOneClearErrorEach) {
    struct Case {
        std::function<void(YAML::Node&)> edit;
        std::string expect;
    };
    const std::vector<Case> cases = {
        {[](YAML::Node& p) { p["hosts"]["b"]["members"].push_back("flight_physics"); }, "placed on two hosts"},
        {[](YAML::Node& p) { p["hosts"]["b"]["members"].push_back("autopilot"); }, "'autopilot' is not a component"},
        {[](YAML::Node& p) { p["hosts"]["a"]["clock"] = false; }, "exactly one host must have 'clock: true'"},
        {[](YAML::Node& p) { p["hosts"]["b"]["address"] = "10.231.0.300"; }, "not an IPv4 address"},
        {[](YAML::Node& p) { p["discovery"] = "broadcast"; }, "discovery"},
        {[](YAML::Node& p) { p["discovery"] = "server"; p["server"]["host"] = "c"; }, "'c' is not a host"},
        {[](YAML::Node& p) {
             YAML::Node ms(YAML::NodeType::Sequence);
             for (const auto& m : p["hosts"]["b"]["members"])
                 if (m.as<std::string>() != "control") ms.push_back(m);
             p["hosts"]["b"]["members"] = ms;
         },
         "'control' of scenario paper2 is on no host"},
        {[](YAML::Node& p) { p["run"]["domain_id"] = 3; }, "set by the plan"},
    };
    int i = 0;
    for (const auto& c : cases) {
        const fs::path plan = plan_with(c.edit, "badplan" + std::to_string(i++));
        const Result r = run({GDNAV_GDNAV_EXE, "host", "--plan", plan.string(), "--name", "b", "--steps", "10",
                              "--out", (plan.parent_path() / "out").string()},
                             30.0);
        EXPECT_EQ(r.exit_code, gdnav::runtime::kExitConfig) << c.expect << "\n" << r.output;
        EXPECT_NE(r.output.find(c.expect), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(plan.string()), std::string::npos) << "the error names the plan file: " << r.output;
        EXPECT_FALSE(fs::exists(plan.parent_path() / "out" / "processes.yaml")) << r.output;
    }
}

TEST(Plan, ScenarioTwoAcrossTwoHostsIsBitIdenticalWithPeersServerAndADegradedLink) {
    if (!can_make_namespaces()) GTEST_SKIP() << "needs root and iproute2 for network namespaces";
    Namespaces ns;
    if (!ns.ok()) GTEST_SKIP() << "cannot create network namespaces here";

    const auto ref_out = temp_dir("plan-onehost");
    const Result ref = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--layout", "composed",
                            "--steps", kSteps, "--record", kRecord, "--out", ref_out.string()},
                           180.0);
    ASSERT_EQ(ref.exit_code, 0) << ref.output;
    const auto one = read_digests(ref_out);
    ASSERT_EQ(one.size(), 5u) << ref.output;

    const PlanRun peers = run_plan(ns, plan_file(), "plan-peers");
    ASSERT_EQ(peers.a, 0) << peers.logs;
    ASSERT_EQ(peers.b, 0) << peers.logs;
    EXPECT_EQ(peers.digests, one);

    const fs::path server_plan = plan_with(
        [](YAML::Node& p) {
            p["discovery"] = "server";
            p["server"]["host"] = "a";
            p["server"]["backup"] = "b";
            p["hosts"]["b"]["process"] = "distributed";
        },
        "plan-server");
    const PlanRun server = run_plan(ns, server_plan, "plan-server-run");
    ASSERT_EQ(server.a, 0) << server.logs;
    ASSERT_EQ(server.b, 0) << server.logs;
    EXPECT_NE(server.logs.find("discovery server 0"), std::string::npos) << server.logs;
    EXPECT_NE(server.logs.find("discovery server 1"), std::string::npos) << server.logs;
    EXPECT_EQ(server.digests, one);

    // The degraded link: tc netem (delay, jitter, loss, reordering) where the kernel has it; otherwise (this
    // project's CI VMs have no sch_netem) 1 % random loss each way with nftables.
    const bool netem = ns.netem({"delay", "5ms", "1ms", "loss", "1%", "reorder", "5%"});
    const std::string link_kind = netem ? "netem delay 5 ms +-1 ms, 1% loss, 5% reordering"
                                        : "1% UDP loss each way (nftables; no sch_netem in this kernel: no delay)";
    if (!netem) {
        ASSERT_TRUE(ns.loss(1)) << "neither tc netem nor nftables works here";
    }
    // config/dds/lossy_link.xml: 50 ms writer heartbeats, so a lost sample is repaired in ~50 ms, not up to 3 s.
    const fs::path slow_plan = plan_with(
        [](YAML::Node& p) {
            p["run"]["member_timeout_s"] = 10;
            p["dds_profile"] = "dds/lossy_link.xml";
        },
        "plan-netem");
    const PlanRun degraded = run_plan(ns, slow_plan, "plan-netem-run");
    ns.netem({});
    ns.loss(0);
    ASSERT_EQ(degraded.a, 0) << degraded.logs;
    ASSERT_EQ(degraded.b, 0) << degraded.logs;
    EXPECT_EQ(degraded.digests, one);
    std::printf("scenario #2, %s steps, host a = physics + sensors, host b = filters + guidance + control:\n"
                "  peers %.0f steps/s, discovery server (b distributed) %.0f steps/s, %s: %.0f steps/s\n",
                kSteps, peers.steps_per_s, server.steps_per_s, link_kind.c_str(), degraded.steps_per_s);
}

// Issue 12 item 4: the link cut for less than run.member_timeout_s -> the run resumes and records what the single-host
// run records; cut for longer -> host a's clock declares host b's members dead, and since control and nav_recorder
// are essential the run aborts (exit 3, "run aborted"); host b's members lose the clock and exit; nothing is left
// running in either namespace.
TEST(Plan, LinkCutShorterThanTheMemberTimeoutResumesLongerEndsTheRun) {
    if (!can_make_namespaces()) GTEST_SKIP() << "needs root and iproute2 for network namespaces";
    Namespaces ns;
    if (!ns.ok()) GTEST_SKIP() << "cannot create network namespaces here";
    const auto ref_out = temp_dir("cut-onehost");
    const Result ref = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--layout", "composed",
                            "--steps", kSteps, "--record", kRecord, "--out", ref_out.string()},
                           180.0);
    ASSERT_EQ(ref.exit_code, 0) << ref.output;
    const auto one = read_digests(ref_out);

    // Paced at 4x real time (2000 steps = 5 s of wall time) so the cut lands mid-run; member timeout 3 s.
    const fs::path plan = plan_with(
        [](YAML::Node& p) {
            p["run"]["member_timeout_s"] = 3;
            p["run"]["realtime"] = 4;
        },
        "cut-plan");
    auto start_both = [&](const fs::path& out, pid_t* a, pid_t* b) {
        *a = start(Namespaces::in(ns.a(), {GDNAV_GDNAV_EXE, "run", "--plan", plan.string(), "--steps", kSteps,
                                           "--record", kRecord, "--out", (out / "a").string()}),
                   out / "a.log");
        *b = start(Namespaces::in(ns.b(), {GDNAV_GDNAV_EXE, "host", "--plan", plan.string(), "--name", "b", "--steps",
                                           kSteps, "--record", kRecord, "--out", (out / "b").string()}),
                   out / "b.log");
    };
    auto cut = [&](double after_s, double for_s) {
        std::this_thread::sleep_for(std::chrono::duration<double>(after_s));
        EXPECT_TRUE(ns.link(false));
        std::this_thread::sleep_for(std::chrono::duration<double>(for_s));
        EXPECT_TRUE(ns.link(true));
    };

    const auto short_out = temp_dir("cut-short");
    pid_t a = 0, b = 0;
    start_both(short_out, &a, &b);
    cut(2.0, 1.0);
    const int short_a = wait_for(a, 120.0), short_b = wait_for(b, 30.0);
    const std::string short_logs = read_file(short_out / "a.log") + read_file(short_out / "b.log");
    EXPECT_EQ(short_a, 0) << short_logs;
    EXPECT_EQ(short_b, 0) << short_logs;
    EXPECT_EQ(read_digests(short_out / "b"), one) << short_logs;

    const auto long_out = temp_dir("cut-long");
    start_both(long_out, &a, &b);
    cut(2.0, 8.0);
    const int long_a = wait_for(a, 120.0), long_b = wait_for(b, 30.0);
    const std::string long_logs = read_file(long_out / "a.log") + read_file(long_out / "b.log");
    EXPECT_EQ(long_a, gdnav::runtime::kExitAborted) << long_logs;
    EXPECT_NE(long_b, 0) << long_logs;
    EXPECT_NE(long_logs.find("run aborted"), std::string::npos) << long_logs;
    EXPECT_NE(long_logs.find("lost the clock"), std::string::npos) << long_logs;
    // No orphans: no process of either run is left (their command lines name the run's output directories).
    for (const auto& out : {short_out, long_out}) {
        const Result left = run({"/usr/bin/pgrep", "-f", out.string()}, 10.0);
        EXPECT_NE(left.exit_code, 0) << "processes left: " << left.output;
    }
    std::printf("link cut 1 s (member timeout 3 s): run completed, outputs identical; cut 8 s: host a exit %d (run "
                "aborted: essential members on host b dead), host b exit %d\n",
                long_a, long_b);
}
