// Issue 5: kill the GNSS process with SIGKILL mid-run in a distributed run. The run completes, nav_pos reports
// "GNSS lost" within 1 s of simulated time after the clock declares the publisher dead, estimates stay bounded.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <cmath>
#include <regex>
#include <thread>

#include "process_util.hpp"
#include "record_reader.hpp"

using namespace gdnav::testing;

TEST(GnssKill, NavPosSwitchesToDeniedWhenTheGnssPublisherDies) {
    const auto out = temp_dir("gnsskill");
    // t = -50 s ... 70 s as fast as it goes; the scheduled loss (t = 100 s) is never reached.
    const pid_t launcher = start({GDNAV_GDNAV_EXE, "run", "--scenario", "nav_loop_s2", "--layout", "distributed",
                                  "--out", out.string(), "--steps", "12000"},
                                 out / "log.txt");
    std::map<std::string, pid_t> procs;
    for (int i = 0; i < 1000 && procs.size() < 2; ++i) {
        procs = read_processes(out);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_TRUE(procs.count("sensors_gnss")) << read_file(out / "log.txt");
    // Wait until the run is under way (t > -10 s), then kill the receiver.
    const std::string start_marker = "run 0 starts";
    for (int i = 0; i < 3000 && read_file(out / "log.txt").find(start_marker) == std::string::npos; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    std::this_thread::sleep_for(std::chrono::milliseconds(3000));
    ASSERT_EQ(kill(procs.at("sensors_gnss"), SIGKILL), 0);
    const int code = wait_for(launcher, 120.0);
    const std::string log = read_file(out / "log.txt");
    ASSERT_EQ(code, 0) << log;

    std::smatch m;
    ASSERT_TRUE(std::regex_search(log, m, std::regex(R"(member 'sensors_gnss' declared dead at step (\d+) \(t = ([-0-9.]+) s\))")))
        << log;
    const double t_dead = std::stod(m[2]);
    ASSERT_TRUE(std::regex_search(log, m, std::regex(R"(\[nav_pos\] t=([-0-9.]+) s: GNSS lost: the GNSS publisher was declared dead)")))
        << log;
    const double t_lost = std::stod(m[1]);
    std::printf("GNSS publisher declared dead at t = %.2f s; nav_pos GNSS-denied at t = %.2f s\n", t_dead, t_lost);
    EXPECT_GE(t_lost, t_dead - 0.011);
    EXPECT_LE(t_lost, t_dead + 1.0);

    // Estimates stay bounded: horizontal error and attitude until the end of the run.
    const auto truth = read_records<gdnav::msg::Truth>(out, "gdnav/Truth");
    const auto pos = read_records<gdnav::msg::PositionEstimate>(out, "gdnav/PositionEstimate");
    ASSERT_EQ(truth.size(), 12000u);
    ASSERT_EQ(pos.size(), 12000u);
    const double R = 6.37e6;
    double worst = 0.0;
    for (std::size_t i = 0; i < pos.size(); ++i) {
        const double dn = (pos[i].lat_rad() - truth[i].lat_rad()) * R;
        const double de = (pos[i].lon_rad() - truth[i].lon_rad()) * R * std::cos(truth[i].lat_rad());
        worst = std::max(worst, std::hypot(dn, de));
    }
    EXPECT_TRUE(pos.back().gnss_denied());
    // Up to ~110 s without GNSS at ~29 m/s: a few percent of ~3 km, far below divergence.
    EXPECT_LT(worst, 500.0);
    std::printf("largest horizontal error %.1f m\n", worst);
}
