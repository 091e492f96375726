// A DDS domain given on the command line is used, or the command refuses with one line (docs/replay.md,
// docs/montecarlo.md "DDS domains"):
//  - `gdnav run --replay RUN --domain D` runs on D (not on a fresh domain the launcher picks);
//  - `gdnav montecarlo --domain D --jobs J` runs slot k on D + k;
//  - domains past 232 (the highest DDS domain) are refused before anything starts, from --domain or run.domain_id.
#include <gtest/gtest.h>

#include <set>

#include <yaml-cpp/yaml.h>

#include "process_util.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

// Domains of these tests (no other test uses 196-199).
constexpr int kReplayDomain = 196;
constexpr int kBatchDomain = 197;  // and 198 (two slots)

int domain_of(const fs::path& run_dir) {
    return YAML::LoadFile((run_dir / "run.yaml").string())["run"]["domain_id"].as<int>();
}

}  // namespace

TEST(DomainGiven, ReplayRunsOnTheGivenDomain) {
    const fs::path dir = temp_dir("domain-replay");
    const std::string topics = "ImuSample,MagSample,AirSample,AtmSample,GnssSample,Truth";
    const Result rec = run({kExe, "run", "--scenario", "paper2", "--steps", "300", "--layout", "direct", "--record",
                            topics, "--out", (dir / "orig").string()},
                           120.0);
    ASSERT_EQ(rec.exit_code, 0) << rec.output;

    const Result rep = run({kExe, "run", "--replay", (dir / "orig").string(), "--topics", topics, "--layout",
                            "composed", "--domain", std::to_string(kReplayDomain), "--out", (dir / "replay").string()},
                           120.0);
    ASSERT_EQ(rep.exit_code, 0) << rep.output;
    EXPECT_EQ(domain_of(dir / "replay"), kReplayDomain) << rep.output;
    fs::remove_all(dir);
}

TEST(DomainGiven, BatchSlotsRunOnConsecutiveDomainsFromTheGivenOne) {
    const fs::path dir = temp_dir("domain-batch");
    const Result r = run({kExe, "montecarlo", "--scenario", "2", "--runs", "3", "--jobs", "2", "--steps", "300",
                          "--layout", "composed", "--domain", std::to_string(kBatchDomain), "--no-report", "--out",
                          (dir / "batch").string()},
                         180.0);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    std::set<int> used;
    for (const auto& e : fs::directory_iterator(dir / "batch" / "runs")) used.insert(domain_of(e.path()));
    EXPECT_EQ(used.count(kBatchDomain), 1u) << "the first run takes slot 0";
    for (const int d : used) EXPECT_TRUE(d == kBatchDomain || d == kBatchDomain + 1) << "domain " << d;
    EXPECT_NE(r.output.find("DDS domains 197..198"), std::string::npos) << r.output;
    fs::remove_all(dir);
}

TEST(DomainGiven, BatchDomainsPastTheLastOneAreRefusedWithOneLine) {
    const fs::path dir = temp_dir("domain-batch-bad");
    const Result flag = run({kExe, "montecarlo", "--scenario", "2", "--runs", "2", "--jobs", "2", "--layout",
                             "composed", "--domain", "232", "--out", (dir / "a").string()});
    EXPECT_EQ(flag.exit_code, 2) << flag.output;
    EXPECT_EQ(count_of(flag.output, "above 232"), 1u) << flag.output;
    EXPECT_EQ(count_of(flag.output, "] error: "), 1u) << "one line: " << flag.output;
    EXPECT_FALSE(fs::exists(dir / "a" / "runs")) << "nothing started";

    const Result key = run({kExe, "montecarlo", "--scenario", "2", "--runs", "3", "--jobs", "3", "--layout",
                            "composed", "--set", "run.domain_id=231", "--out", (dir / "b").string()});
    EXPECT_EQ(key.exit_code, 2) << key.output;
    EXPECT_NE(key.output.find("run.domain_id 231 with --jobs 3"), std::string::npos) << key.output;
    fs::remove_all(dir);
}
