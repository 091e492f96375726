// The same run split across two "hosts": two network namespaces joined by a veth pair, created by this test.
// Host A runs the clock, plant and sensor; host B the filter, controller and recorder. DDS discovery uses unicast
// initial peers (config/dds/two_hosts_udp.xml, UDP only). The recorded outputs must equal the single-host run's.
// Needs root (ip netns); skipped otherwise.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include <yaml-cpp/yaml.h>

#include "netns.hpp"
#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;


TEST(TwoHosts, SplitRunRecordsTheSameOutputsAsOneHost) {
    if (!can_make_namespaces()) GTEST_SKIP() << "needs root and iproute2 for network namespaces";
    Namespaces ns;
    if (!ns.ok()) GTEST_SKIP() << "cannot create network namespaces here";

    // Reference: the single-host run.
    const auto ref_out = temp_dir("onehost");
    const Result ref = run({testchain_exe(), "run", "--scenario", chain_scenario(), "--layout", "distributed", "--out",
                            ref_out.string()});
    ASSERT_EQ(ref.exit_code, 0) << ref.output;

    // The split run's config: same scenario, two-host DDS profile, fixed domain.
    const auto out = temp_dir("twohosts");
    YAML::Node doc = YAML::LoadFile(chain_scenario());
    doc["run"]["dds_profile"] = std::string(GDNAV_SOURCE_DIR) + "/config/dds/two_hosts_udp.xml";
    doc["run"]["domain_id"] = 7;
    doc["run"]["out_dir"] = out.string();
    doc["run"]["startup_timeout_s"] = 60;
    const fs::path cfg = out / "run.yaml";
    std::ofstream(cfg) << doc;

    auto in_ns = [&](const std::string& ns_name, std::vector<std::string> args) {
        std::vector<std::string> v{"/usr/bin/env", "ip", "netns", "exec", ns_name, testchain_exe()};
        v.insert(v.end(), args.begin(), args.end());
        v.insert(v.end(), {"--config", cfg.string()});
        return v;
    };
    std::vector<pid_t> pids;
    pids.push_back(start(in_ns(ns.a(), {"clock"}), out / "clock.log"));
    pids.push_back(start(in_ns(ns.a(), {"component", "chain_plant,chain_sensor"}), out / "a.log"));
    pids.push_back(start(in_ns(ns.b(), {"component", "chain_filter,chain_controller,recorder"}), out / "b.log"));
    std::vector<int> codes;
    for (pid_t p : pids) codes.push_back(wait_for(p, 120.0));
    for (std::size_t i = 0; i < codes.size(); ++i)
        EXPECT_EQ(codes[i], 0) << read_file(out / "clock.log") << read_file(out / "a.log") << read_file(out / "b.log");
    const auto two = read_digests(out);
    const auto one = read_digests(ref_out);
    ASSERT_EQ(one.size(), 4u);
    EXPECT_EQ(two, one);
    const YAML::Node summary = YAML::LoadFile((out / "clock_summary.yaml").string());
    std::printf("two-host run: %.0f steps/s over the veth link\n", summary["steps_per_s"].as<double>());
}
