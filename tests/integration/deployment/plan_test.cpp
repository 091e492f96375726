// Issue 12 items 1-3: deployment plans (gdnav run --plan on the clock's host, gdnav host --plan --name on the
// other), in two network namespaces joined by a veth pair: paper scenario #2 with physics and sensors on host a and
// the filters, guidance, control and recorders on host b records exactly what the single-host run records, with
// initial peers, through a Fast DDS discovery server, and over a link degraded by tc netem. Bad plans are one
// error each. The namespace tests need root (skipped otherwise).
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <regex>
#include <thread>

#include <yaml-cpp/yaml.h>

#include "netns.hpp"
#include "process_util.hpp"
#include "framework/lockstep.hpp"

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

// The single-host composed run every plan run is compared with: the digests of its five recorded topics.
std::map<std::string, std::string> single_host_digests(const std::string& tag) {
    const auto out = temp_dir(tag);
    const Result ref = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--layout", "composed",
                            "--steps", kSteps, "--record", kRecord, "--out", out.string()},
                           180.0);
    EXPECT_EQ(ref.exit_code, 0) << ref.output;
    auto digests = read_digests(out);
    EXPECT_EQ(digests.size(), 5u) << ref.output;
    return digests;
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
        EXPECT_EQ(r.exit_code, gdnav::framework::kExitConfig) << c.expect << "\n" << r.output;
        EXPECT_NE(r.output.find(c.expect), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(plan.string()), std::string::npos) << "the error names the plan file: " << r.output;
        EXPECT_FALSE(fs::exists(plan.parent_path() / "out" / "processes.yaml")) << r.output;
    }
}

TEST(Plan, ScenarioTwoAcrossTwoHostsIsBitIdenticalWithPeersMulticastServerAndADegradedLink) {
    if (!can_make_namespaces()) GTEST_SKIP() << "needs root and iproute2 for network namespaces";
    Namespaces ns;
    if (!ns.ok()) GTEST_SKIP() << "cannot create network namespaces here";

    const auto one = single_host_digests("plan-onehost");
    ASSERT_EQ(one.size(), 5u);

    const PlanRun peers = run_plan(ns, plan_file(), "plan-peers");
    ASSERT_EQ(peers.a, 0) << peers.logs;
    ASSERT_EQ(peers.b, 0) << peers.logs;
    EXPECT_EQ(peers.digests, one);

    // Simple discovery (SPDP multicast on the veth link, no addresses in the XML).
    const fs::path mc_plan = plan_with([](YAML::Node& p) { p["discovery"] = "multicast"; }, "plan-multicast");
    const PlanRun multicast = run_plan(ns, mc_plan, "plan-multicast-run");
    ASSERT_EQ(multicast.a, 0) << multicast.logs;
    ASSERT_EQ(multicast.b, 0) << multicast.logs;
    EXPECT_EQ(multicast.digests, one);

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

    // The degraded link, 5 ms +- 1 ms delay, 1 % loss and 5 % reordering each way: tc netem where the kernel has it;
    // otherwise (this project's CI VMs have no sch_netem) gdnav-test-netem on an NFQUEUE (tests/faulty_link); without
    // either, 1 % loss with nftables.
    const auto netem_logs = temp_dir("plan-netem-logs");
    std::string link_kind = "tc netem delay 5 ms +-1 ms, 1% loss, 5% reordering";
    bool queued = false;
    if (!ns.netem({"delay", "5ms", "1ms", "loss", "1%", "reorder", "5%"})) {
        queued = ns.queue_netem(5.0, 1.0, 1.0, 5.0, netem_logs.string());
        link_kind = "delay 5 ms +-1 ms, 1% loss, 5% reordering each way (gdnav-test-netem on an NFQUEUE; no sch_netem)";
        if (!queued) {
            ASSERT_TRUE(ns.loss(1)) << "neither tc netem, gdnav-test-netem nor nftables works here";
            link_kind = "1% UDP loss each way (nftables; no sch_netem and no gdnav-test-netem: no delay)";
        }
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
    ns.queue_netem_stop();
    ns.loss(0);
    if (queued) {
        // The tool really delayed, dropped and reordered packets of this run (its counts, printed at its end).
        const std::string counts = read_file(netem_logs / "netem_a.log") + read_file(netem_logs / "netem_b.log");
        std::smatch m;
        std::string rest = counts;
        int seen = 0;
        const std::regex re(R"((\d+) packets: (\d+) delayed, (\d+) released at once \(reordered\), (\d+) dropped)");
        while (std::regex_search(rest, m, re)) {
            EXPECT_GT(std::stoull(m[2]), 1000u) << counts;
            EXPECT_GT(std::stoull(m[3]), 0u) << counts;
            EXPECT_GT(std::stoull(m[4]), 0u) << counts;
            ++seen;
            rest = m.suffix();
        }
        EXPECT_EQ(seen, 2) << counts;
        std::printf("%s", counts.c_str());
    }
    ASSERT_EQ(degraded.a, 0) << degraded.logs;
    ASSERT_EQ(degraded.b, 0) << degraded.logs;
    EXPECT_EQ(degraded.digests, one);
    std::printf("scenario #2, %s steps, host a = physics + sensors, host b = filters + guidance + control:\n"
                "  peers %.0f steps/s, multicast %.0f steps/s, discovery server (b distributed) %.0f steps/s,\n"
                "  %s: %.0f steps/s\n",
                kSteps, peers.steps_per_s, multicast.steps_per_s, server.steps_per_s, link_kind.c_str(),
                degraded.steps_per_s);
}

// Issue 12 item 4: the link cut for less than run.member_timeout_s -> the run resumes and records what the single-host
// run records; cut for longer -> host a's clock declares host b's members dead, and since control and nav_recorder
// are essential the run aborts (exit 3, "run aborted"); host b's members lose the clock and exit; nothing is left
// running in either namespace.
TEST(Plan, LinkCutShorterThanTheMemberTimeoutResumesLongerEndsTheRun) {
    if (!can_make_namespaces()) GTEST_SKIP() << "needs root and iproute2 for network namespaces";
    Namespaces ns;
    if (!ns.ok()) GTEST_SKIP() << "cannot create network namespaces here";
    const auto one = single_host_digests("cut-onehost");
    ASSERT_EQ(one.size(), 5u);

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
    EXPECT_EQ(long_a, gdnav::framework::kExitAborted) << long_logs;
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

// Benchmark, not run by CTest (tests never assert on wall time): steps/s of the two-host plan against link delay,
// loss and reordering, and whether the outputs still equal the single-host run's. Run with
//   build/tests/test_integration_plan --gtest_also_run_disabled_tests --gtest_filter='*Bench*'
TEST(Plan, DISABLED_BenchStepsPerSecondAgainstLinkDelayLossAndReordering) {
    if (!can_make_namespaces()) GTEST_SKIP() << "needs root and iproute2 for network namespaces";
    Namespaces ns;
    if (!ns.ok()) GTEST_SKIP() << "cannot create network namespaces here";
    const auto one = single_host_digests("bench-onehost");
    ASSERT_EQ(one.size(), 5u);
    struct Case {
        double delay_ms, jitter_ms, loss_pct, reorder_pct;
        bool lossy_profile;
    };
    const std::vector<Case> cases = {{0, 0, 0, 0, false},  {1, 0, 0, 0, false},   {5, 1, 0, 0, false},
                                     {20, 2, 0, 0, false}, {5, 1, 0, 5, false},   {5, 1, 1, 5, true},
                                     {1, 0, 1, 0, true},   {20, 2, 1, 5, true}};
    std::printf("| delay [ms] | jitter [ms] | loss each way [%%] | reordered [%%] | DDS profile | steps/s | outputs |\n"
                "|--:|--:|--:|--:|---|--:|---|\n");
    int i = 0;
    for (const Case& c : cases) {
        const auto logs = temp_dir("bench-netem-" + std::to_string(i));
        const bool shaped = c.delay_ms == 0 && c.loss_pct == 0 && c.reorder_pct == 0
                                ? true
                                : ns.queue_netem(c.delay_ms, c.jitter_ms, c.loss_pct, c.reorder_pct, logs.string());
        ASSERT_TRUE(shaped) << "gdnav-test-netem is not available (tests/faulty_link)";
        const fs::path plan = plan_with(
            [&](YAML::Node& p) {
                p["run"]["member_timeout_s"] = 20;
                if (c.lossy_profile) p["dds_profile"] = "dds/lossy_link.xml";
            },
            "bench-plan-" + std::to_string(i));
        const PlanRun r = run_plan(ns, plan, "bench-run-" + std::to_string(i++));
        ns.queue_netem_stop();
        std::printf("| %g | %g | %g | %g | %s | %.0f | %s |\n", c.delay_ms, c.jitter_ms, c.loss_pct, c.reorder_pct,
                    c.lossy_profile ? "lossy_link.xml" : "default", r.steps_per_s,
                    r.a != 0 || r.b != 0 ? "run failed" : (r.digests == one ? "bit-identical" : "DIFFERENT"));
        std::fflush(stdout);
    }
}

// Issue 12 items 1 + 5: the two-host plan with DDS Security (`run.security` in the plan): three secure participants
// (the clock and host a's process in namespace a, host b's process in namespace b, each host's process under the
// `composed` identity of `gdnav pki init`), outputs bit-identical to the plain single-host run.
TEST(Plan, SecureTwoHostRunIsBitIdenticalToThePlainSingleHostRun) {
    if (!can_make_namespaces()) GTEST_SKIP() << "needs root and iproute2 for network namespaces";
    Namespaces ns;
    if (!ns.ok()) GTEST_SKIP() << "cannot create network namespaces here";
    const auto one = single_host_digests("secplan-onehost");
    ASSERT_EQ(one.size(), 5u);

    const fs::path pki = temp_dir("secplan-pki") / "pki";
    const Result init = run({GDNAV_GDNAV_EXE, "pki", "init", pki.string(), "--scenario", "paper2"}, 120.0);
    ASSERT_EQ(init.exit_code, 0) << init.output;
    const fs::path plan = plan_with([&](YAML::Node& p) { p["run"]["security"] = pki.string(); }, "secplan");
    const PlanRun secure = run_plan(ns, plan, "secplan-run");
    ASSERT_EQ(secure.a, 0) << secure.logs;
    ASSERT_EQ(secure.b, 0) << secure.logs;
    EXPECT_NE(secure.logs.find("DDS Security on"), std::string::npos) << secure.logs;
    EXPECT_EQ(secure.digests, one);
    std::printf("secure two-host plan (peers, both hosts composed): %.0f steps/s\n", secure.steps_per_s);
}
