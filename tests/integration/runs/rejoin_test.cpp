// Issue 11, item 4: a member killed for real (SIGKILL) comes back into the running run with
// `gdnav component NAME --config RUN.yaml --rejoin`. Scenario #2 with GNSS lost at t = 20 s, paced at 4x real time:
// sensors_gnss is SIGKILLed near t = -40 s, declared dead (nav_pos goes GNSS-denied), restarted; the clock admits it
// at a step boundary, fixes resume, nav_pos re-acquires, and the fixes stop again at the scheduled loss time.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <regex>
#include <thread>

#include <yaml-cpp/yaml.h>

#include "process_util.hpp"
#include "record_reader.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;

namespace {

std::string fresh_domain() { return std::to_string(145 + static_cast<int>(getpid() % 5)); }

bool wait_for_text(const fs::path& log, const std::string& text, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < end) {
        if (read_file(log).find(text) != std::string::npos) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return false;
}

}  // namespace

TEST(Rejoin, KilledGnssPublisherComesBackAndNavPosReacquires) {
    const fs::path dir = temp_dir("rejoin");
    const fs::path cfg = dir / "paper2.yaml";
    const Result s = run({GDNAV_GDNAV_EXE, "scenario", "--scenario", "2", "--seed", "1", "--set", "generator.t_gnss_s=20",
                          "--set", "components.recorder={type: recorder, topics: [gdnav/GnssSample]}", "--out",
                          cfg.string()});
    ASSERT_EQ(s.exit_code, 0) << s.output;
    const fs::path out = dir / "run";
    const fs::path log = dir / "run.log";
    const std::string domain = fresh_domain();
    const pid_t launcher = start({GDNAV_GDNAV_EXE, "run", "--scenario", cfg.string(), "--layout", "distributed",
                                  "--steps", "9001", "--realtime", "4", "--domain", domain, "--out", out.string(),
                                  "--set", "run.member_timeout_s=2"},
                                 log);
    ASSERT_TRUE(wait_for_text(log, "run 0 starts", 120.0)) << read_file(log);
    std::this_thread::sleep_for(std::chrono::seconds(2));
    const auto procs = read_processes(out);
    ASSERT_TRUE(procs.count("sensors_gnss")) << read_file(log);
    ASSERT_EQ(kill(procs.at("sensors_gnss"), SIGKILL), 0);
    ASSERT_TRUE(wait_for_text(log, "member 'sensors_gnss' declared dead", 30.0)) << read_file(log);
    const pid_t back = start({GDNAV_GDNAV_EXE, "component", "sensors_gnss", "--config", (out / "run.yaml").string(),
                              "--rejoin"},
                             dir / "rejoin.log");
    const int back_code = wait_for(back, 120.0);
    const int code = wait_for(launcher, 120.0);
    if (back_code == -1) kill(back, SIGKILL);
    if (code == -1) kill(launcher, SIGINT);
    const std::string text = read_file(log);
    std::printf("%s", text.substr(text.size() > 6000 ? text.size() - 6000 : 0).c_str());
    EXPECT_EQ(back_code, 0) << read_file(dir / "rejoin.log");

    std::smatch m;
    ASSERT_TRUE(std::regex_search(text, m, std::regex("member 'sensors_gnss' rejoins from \\S+ at step (\\d+)"))) << text;
    const std::uint64_t k_back = std::stoull(m[1]);
    const double t_back = -50.0 + 0.01 * static_cast<double>(k_back);
    EXPECT_NE(text.find("GNSS lost: the GNSS publisher was declared dead"), std::string::npos) << text;
    EXPECT_NE(text.find("GNSS re-acquired"), std::string::npos) << text;
    // The run is not reproducible (a member died at a wall-clock moment) and says who came back.
    const YAML::Node summary = YAML::LoadFile((out / "clock_summary.yaml").string());
    EXPECT_FALSE(summary["reproducible"].as<bool>());
    ASSERT_EQ(summary["rejoined_members"].size(), 1u);

    // Fixes: none recorded while it was dead, valid 1 Hz fixes again after k_back until t = 20 s, none after.
    const auto gnss = read_records<gdnav::msg::GnssSample>(out, "gdnav/GnssSample");
    int valid_back = 0, valid_after_loss = 0;
    for (const auto& g : gnss) {
        const double t = g.stamp().t_s();
        if (!g.fix_valid()) continue;
        if (t >= t_back && t <= 20.0) ++valid_back;  // the receiver's last fix is the one at t_GNSS itself
        if (t > 20.0) ++valid_after_loss;
    }
    std::printf("sensors_gnss back at t = %.2f s; %d valid fixes after it, %d after the loss time (20 s)\n", t_back,
                valid_back, valid_after_loss);
    EXPECT_LT(t_back, 20.0);
    EXPECT_GE(valid_back, static_cast<int>(20.0 - t_back) - 1);
    EXPECT_EQ(valid_after_loss, 0);
    EXPECT_EQ(code, 0) << text;
}
