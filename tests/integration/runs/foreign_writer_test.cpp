// Only the producers' samples are used (docs/protocol.md §2.5): a plain participant (it announces no member) writes
// gdnav/AirSample with the run's id and the steps the run is at, beside a distributed run that records every topic.
// The run's recorded topics and metrics are those of the same run without it, its samples are counted as rejected
// in clock_summary.yaml, and the consumers' warnings about them are rate-limited.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <atomic>
#include <chrono>
#include <map>
#include <thread>

#include "process_util.hpp"
#include "dds/dds_context.hpp"
#include "framework/run_config.hpp"
#include "framework/topic_types.hpp"
#include "msgs/messages.hpp"

using namespace gdnav::testing;
namespace msg = gdnav::msg;
namespace framework = gdnav::framework;
using namespace eprosima::fastdds::dds;

namespace {

constexpr int kDomain = 154;  // integration tests run one at a time (RUN_SERIAL)
constexpr std::uint64_t kSteps = 1500;
constexpr std::uint64_t kAhead = 64;  // the rogue writes the steps from the clock's last Tick to this many ahead

std::vector<std::string> run_args(const std::filesystem::path& out) {
    return {GDNAV_GDNAV_EXE, "run",      "--scenario", "default",    "--layout", "distributed", "--steps",
            std::to_string(kSteps), "--domain", std::to_string(kDomain), "--record", "all", "--out", out.string()};
}

// A plain participant (no member announced): follows the clock's Ticks and writes an AirSample (default values, a
// valid stamp) for every step from the Tick on, kAhead steps ahead, until `stop`. Returns how many it wrote.
std::uint64_t rogue(const std::atomic<bool>& stop) {
    gdnav::dds::DdsContext dds(kDomain, framework::config_dir() / "dds" / "gdnav_profiles.xml", "rogue");
    const auto& air = msg::message_ops<gdnav::msg::AirSample>();
    const auto& tick_ops = msg::message_ops<gdnav::msg::Tick>();
    DataWriter* w = dds.writer(gdnav::topics::kAir, air, gdnav::dds::kDataWriterProfile);
    DataReader* ticks = dds.reader(gdnav::topics::kTick, tick_ops, gdnav::dds::kControlReaderProfile);
    gdnav::msg::AirSample s;
    s.tas_mps(55.0);
    s.aoa_rad(0.3);
    gdnav::msg::Tick t;
    SampleInfo info;
    std::uint64_t next = 0, written = 0;
    while (!stop.load()) {
        std::uint64_t tick = UINT64_MAX;
        while (ticks->take_next_sample(&t, &info) == ReturnCode_t::RETCODE_OK)
            if (info.valid_data && t.stamp().run_id() == 0) tick = std::max(tick == UINT64_MAX ? 0 : tick, t.stamp().step());
        if (tick != UINT64_MAX)
            for (next = std::max(next, tick); next <= tick + kAhead && next < kSteps; ++next, ++written) {
                air.set_stamp(&s, 0, next, 0.01 * static_cast<double>(next));
                w->write(&s);
            }
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return written;
}

}  // namespace

TEST(ForeignWriter, APlainParticipantOnADataTopicChangesNothingAndIsCounted) {
    framework::register_gdnav_topics();
    const auto ref = temp_dir("foreign-ref");
    const Result r0 = run(run_args(ref), 180.0);
    ASSERT_EQ(r0.exit_code, 0) << r0.output;
    const auto expected = read_digests(ref);
    ASSERT_GT(expected.count(gdnav::topics::kAir), 0u) << r0.output;

    const auto out = temp_dir("foreign-run");
    std::atomic<bool> stop{false};
    std::uint64_t written = 0;
    std::thread writer([&] { written = rogue(stop); });
    const Result r1 = run(run_args(out), 180.0);
    stop.store(true);
    writer.join();
    ASSERT_EQ(r1.exit_code, 0) << r1.output;
    std::printf("the rogue wrote %llu AirSample samples during the run\n", static_cast<unsigned long long>(written));
    ASSERT_GT(written, 0u);

    // Nothing it wrote was used: every recorded topic and the metrics are those of the run alone.
    EXPECT_EQ(read_digests(out), expected);
    EXPECT_EQ(read_file(out / "metrics.yaml"), read_file(ref / "metrics.yaml"));

    // Counted: by nav_air and the recorder (the AirSample consumers), as not from the producer, no bad stamp.
    const YAML::Node summary = YAML::LoadFile((out / "clock_summary.yaml").string());
    std::map<std::string, std::uint64_t> foreign;
    for (const auto& e : summary["rejected_samples"]) {
        EXPECT_EQ(e["topic"].as<std::string>(), gdnav::topics::kAir);
        EXPECT_EQ(e["bad_stamp"].as<std::uint64_t>(), 0u);
        foreign[e["member"].as<std::string>()] = e["not_from_producer"].as<std::uint64_t>();
    }
    EXPECT_GT(foreign["nav_air"], 0u) << read_file(out / "clock_summary.yaml");
    EXPECT_GT(foreign["recorder"], 0u) << read_file(out / "clock_summary.yaml");
    EXPECT_TRUE(summary["reproducible_claim"]) << read_file(out / "clock_summary.yaml");
    const YAML::Node clean = YAML::LoadFile((ref / "clock_summary.yaml").string());
    EXPECT_EQ(clean["rejected_samples"].size(), 0u);
    EXPECT_FALSE(clean["reproducible_claim"]);

    // Rate-limited: one line at the first rejection, then at most one per 5 s (the run takes a few seconds), and
    // one total per input at the end.
    const std::size_t lines = count_of(r1.output, "not written by its producer (sensors_air) dropped");
    EXPECT_GE(lines, 2u) << r1.output;
    EXPECT_LE(lines, 8u) << r1.output;
    EXPECT_EQ(count_of(r1.output, "': rejected "), 2u) << r1.output;
}
