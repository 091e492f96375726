// The lockstep protocol from outside gdnav: gdnav-raw-member (raw_member.cpp, written from docs/protocol.md with the
// raw Fast DDS API and the generated types only) replaces chain_controller in a test-chain run and reproduces the
// all-built-in run bit for bit; announcing another protocol version gets it refused with the clock's clear error; a
// sample of its with a non-finite time is rejected and counted by its consumers.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "process_util.hpp"
#include "gdnav.h"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

// A DDS domain of this test's own (launcher defaults: 20-219 from its pid; other external-member tests: 150-232).
std::string fresh_domain() {
    static int n = 0;
    return std::to_string(120 + static_cast<int>((getpid() + n++) % 20));
}

using Pair = PairResult;

// `gdnav-testchain run <args> --external chain_controller --domain D --out OUT` and the raw member on domain D.
Pair run_with_raw_member(std::vector<std::string> run_args, std::vector<std::string> member_args, const fs::path& out,
                         double timeout_s) {
    const std::string domain = fresh_domain();
    run_args.insert(run_args.begin(), testchain_exe());
    for (const std::string a : {"--external", "chain_controller", "--domain", domain.c_str(), "--out"}) run_args.push_back(a);
    run_args.push_back(out.string());
    member_args.insert(member_args.begin(), {GDNAV_RAW_MEMBER_EXE, "--domain", domain});
    return run_pair(run_args, member_args, out, timeout_s);
}

}  // namespace

TEST(RawMember, ReplacesChainControllerBitForBit) {
    const auto ref = temp_dir("raw-ref");
    const Result r0 = run({testchain_exe(), "run", "--scenario", chain_scenario(), "--layout", "distributed", "--seed", "1",
                           "--out", ref.string()},
                          180.0);
    ASSERT_EQ(r0.exit_code, 0) << r0.output;
    const auto expected = read_digests(ref);
    ASSERT_EQ(expected.size(), 4u) << r0.output;  // chain/state, chain/meas, chain/estimate, chain/control

    const auto out = temp_dir("raw-ext");
    const Pair p = run_with_raw_member({"run", "--scenario", chain_scenario(), "--layout", "distributed", "--seed", "1"}, {},
                                       out, 180.0);
    ASSERT_EQ(p.run_code, 0) << p.run_log << "\n--- member:\n" << p.member_log;
    EXPECT_EQ(p.member_code, 0) << p.member_log;
    EXPECT_NE(p.run_log.find("external member 'chain_controller' joined"), std::string::npos) << p.run_log;
    EXPECT_EQ(p.run_log.find("declared dead"), std::string::npos) << p.run_log;
    const auto got = read_digests(out);
    EXPECT_EQ(got, expected) << p.run_log;
    for (const auto& [topic, digest] : got) std::printf("%s: %s (built-in %s)\n", topic.c_str(), digest.c_str(),
                                                        expected.count(topic) ? expected.at(topic).c_str() : "-");
}

TEST(RawMember, WrongProtocolVersionIsRefusedAndTheRunEndsAtTheJoinTimeout) {
    const auto out = temp_dir("raw-version");
    const Pair p = run_with_raw_member(
        {"run", "--scenario", chain_scenario(), "--layout", "distributed", "--join-timeout", "3"},
        {"--protocol-version", "99"}, out, 60.0);
    EXPECT_EQ(p.run_code, 5) << p.run_log;
    // §3.1: one error naming the member, its host and both versions.
    const std::string refused = "member 'chain_controller' (";
    const auto at = p.run_log.find(refused);
    ASSERT_NE(at, std::string::npos) << p.run_log;
    const std::string versions = "speaks lockstep protocol version 99, this clock speaks " +
                                 std::to_string(gdnav::msg::LOCKSTEP_PROTOCOL_VERSION) + ": refused";
    EXPECT_NE(p.run_log.find(versions, at), std::string::npos)
        << p.run_log;
    EXPECT_EQ(p.run_log.find(refused, at + 1), std::string::npos) << "logged more than once:\n" << p.run_log;
    EXPECT_NE(p.run_log.find("external member 'chain_controller' did not join within 3 s"), std::string::npos) << p.run_log;
    // §5: the member hears the clock's ABORT (the clock exits 5) and exits 3.
    EXPECT_EQ(p.member_code, 3) << p.member_log;
}

TEST(RawMember, ASampleWithANonFiniteTimeIsRejectedAndCounted) {
    // The producer's own sample of step 100 has t_s NaN: both consumers of chain/control (the plant and the recorder)
    // reject it and step without it, as without a sample; the run completes and clock_summary.yaml counts it.
    const auto out = temp_dir("raw-nan");
    const Pair p = run_with_raw_member({"run", "--scenario", chain_scenario(), "--layout", "distributed", "--seed", "1"},
                                       {"--nan-t-at", "100"}, out, 180.0);
    ASSERT_EQ(p.run_code, 0) << p.run_log << "\n--- member:\n" << p.member_log;
    EXPECT_EQ(p.member_code, 0) << p.member_log;
    const YAML::Node summary = YAML::LoadFile((out / "clock_summary.yaml").string());
    std::map<std::string, std::pair<std::uint64_t, std::uint64_t>> got;
    for (const auto& e : summary["rejected_samples"]) {
        EXPECT_EQ(e["topic"].as<std::string>(), "chain/control");
        got[e["member"].as<std::string>()] = {e["not_from_producer"].as<std::uint64_t>(), e["bad_stamp"].as<std::uint64_t>()};
    }
    const std::map<std::string, std::pair<std::uint64_t, std::uint64_t>> want{{"chain_plant", {0, 1}}, {"recorder", {0, 1}}};
    EXPECT_EQ(got, want) << read_file(out / "clock_summary.yaml");
    EXPECT_NE(p.run_log.find("sample(s) with a bad stamp rejected"), std::string::npos) << p.run_log;
    EXPECT_NE(p.run_log.find("t_s nan: t_s not finite"), std::string::npos) << p.run_log;
    // The recording has no chain/control sample of step 100 (1999 of 2000).
    const YAML::Node digest = YAML::LoadFile((out / "record" / "digest.yaml").string());
    EXPECT_EQ(digest["topics"]["chain/control"]["samples"].as<std::uint64_t>(), 1999u);
}
