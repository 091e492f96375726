// Recordings are MCAP (docs/viewing.md).
//   (a) a recorder killed mid-run (SIGKILL, distributed layout) leaves an MCAP file without summary: gdnav's reader
//       reports it clearly and everything before the cut is readable, bit-identical to an uninterrupted recording,
//       and replays (--steps up to the cut);
// Size and cost of a recording (printed, not asserted) are a study of their own: mcap_cost_test.cpp.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <filesystem>
#include <regex>
#include <thread>

#include "process_util.hpp"
#include "io/recording/record_file.hpp"
#include "framework/topic_types.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {
}

TEST(Mcap, RecorderKilledMidRunLeavesEverythingBeforeTheCutReadable) {
    gdnav::framework::register_gdnav_topics();
    const fs::path out = temp_dir("mcap-killed");
    // Scenario #2 paced at 10x real time (6001 steps: about 6 s), the recorder in its own process writing 1 MiB
    // chunks (one every ~950 steps with these six topics).
    const pid_t launcher = start({kExe, "run", "--scenario", "paper2", "--seed", "1", "--steps", "6001", "--layout",
                                  "distributed", "--realtime", "10", "--record", "default,Truth", "--out", out.string()},
                                 out / "log.txt");
    std::map<std::string, pid_t> procs;
    for (int i = 0; i < 3000 && !procs.count("recorder"); ++i) {
        procs = read_processes(out);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_TRUE(procs.count("recorder")) << read_file(out / "log.txt");
    // Kill the recorder once two chunks are on disk (the file grows chunk by chunk, ~0.5 MB each).
    const fs::path file = out / "record" / "run.mcap";
    std::error_code ec;
    for (int i = 0; i < 6000 && (!fs::exists(file, ec) || fs::file_size(file, ec) < 900000); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_GE(fs::file_size(file, ec), 900000u) << read_file(out / "log.txt");
    ASSERT_EQ(kill(procs.at("recorder"), SIGKILL), 0);
    ASSERT_EQ(wait_for(launcher, 120.0), 0) << read_file(out / "log.txt");  // the recorder is not essential
    EXPECT_FALSE(fs::exists(out / "record" / "digest.yaml"));

    const gdnav::io::recording::Recording cut = gdnav::io::recording::read_recording(out / "record");
    EXPECT_FALSE(cut.complete);
    EXPECT_NE(cut.problem.find("at byte"), std::string::npos) << cut.problem;
    std::printf("killed recording: %s (%ju bytes); %s\n", file.string().c_str(),
                static_cast<std::uintmax_t>(fs::file_size(file)), cut.problem.c_str());
    ASSERT_EQ(cut.topics.size(), 6u);
    std::uint64_t last = UINT64_MAX;
    for (const auto& [topic, tr] : cut.topics) {
        ASSERT_FALSE(tr.entries.empty()) << topic;
        for (std::size_t i = 0; i < tr.entries.size(); ++i) ASSERT_EQ(tr.entries[i].step, i) << topic;
        last = std::min<std::uint64_t>(last, tr.entries.back().step);
        std::printf("  %s: steps 0..%ju readable\n", topic.c_str(), static_cast<std::uintmax_t>(tr.entries.back().step));
    }
    EXPECT_LT(last, 6000u);
    EXPECT_EQ(cut.run_metadata.at("seed"), "1");
    EXPECT_FALSE(cut.run_yaml.empty());

    // The same run uninterrupted (direct layout, bit-identical by design): every sample before the cut is equal.
    const fs::path ref = temp_dir("mcap-killed-ref");
    Result r = run({kExe, "run", "--scenario", "paper2", "--seed", "1", "--steps", std::to_string(last + 1), "--layout",
                    "direct", "--record", "default,Truth", "--out", ref.string()});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const gdnav::io::recording::Recording whole = gdnav::io::recording::read_recording(ref / "record");
    ASSERT_TRUE(whole.complete) << whole.problem;
    for (const auto& [topic, tr] : whole.topics) {
        const auto& c = cut.topics.at(topic);
        ASSERT_EQ(tr.entries.size(), last + 1);
        for (std::size_t i = 0; i <= last; ++i) {
            const auto &a = tr.entries[i], &b = c.entries[i];
            ASSERT_EQ(a.size, b.size);
            ASSERT_TRUE(std::equal(&tr.bytes[a.offset], &tr.bytes[a.offset] + a.size, &c.bytes[b.offset]))
                << topic << " step " << i;
        }
    }
    // And it replays (the filters on the recorded sensors up to the cut); the reader's warning names the cut.
    const fs::path rep = temp_dir("mcap-killed-replay");
    r = run({kExe, "run", "--replay", out.string(), "--topics", "ImuSample,MagSample,AirSample,AtmSample,GnssSample,Truth",
             "--steps", std::to_string(last + 1), "--layout", "direct", "--out", rep.string()});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("incomplete MCAP file"), std::string::npos) << r.output;
    if (!::testing::Test::HasFailure())
        for (const auto& d : {out, ref, rep}) fs::remove_all(d);
}
