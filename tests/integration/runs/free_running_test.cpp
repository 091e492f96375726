// A free-running member (hardware-in-the-loop style): not in the lockstep barrier, its consumers use its latest
// sample. The run completes and the clock marks it non-reproducible.
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

#include <yaml-cpp/yaml.h>

#include "process_util.hpp"

using namespace gdnav::testing;

TEST(FreeRunning, MemberOutsideTheBarrierFeedsTheRunWhichIsMarkedNonReproducible) {
    const auto out = temp_dir("freerun");
    YAML::Node doc = YAML::LoadFile(chain_scenario());
    doc["run"]["out_dir"] = out.string();
    doc["run"]["domain_id"] = static_cast<int>(getpid() % 150) + 60;
    // Paced (5 s for 2000 steps): the clock does not wait for a free-running member, so an unpaced run (0.3 s) could
    // end before the sensor's writer has matched the recorder and the filter (two CI runs recorded no chain/meas).
    doc["run"]["realtime"] = 4;
    const auto cfg = out / "run.yaml";
    std::ofstream(cfg) << doc;
    const std::string c = cfg.string();
    const pid_t clock = start({testchain_exe(), "clock", "--config", c}, out / "clock.log");
    const pid_t host = start({testchain_exe(), "component", "chain_plant,chain_filter,chain_controller,recorder",
                              "--config", c},
                             out / "host.log");
    const pid_t sensor =
        start({testchain_exe(), "component", "chain_sensor", "--free-running", "--config", c}, out / "sensor.log");
    EXPECT_EQ(wait_for(clock, 120.0), 0) << read_file(out / "clock.log");
    EXPECT_EQ(wait_for(host, 30.0), 0) << read_file(out / "host.log");
    EXPECT_EQ(wait_for(sensor, 30.0), 0) << read_file(out / "sensor.log");
    const YAML::Node summary = YAML::LoadFile((out / "clock_summary.yaml").string());
    EXPECT_TRUE(summary["completed"].as<bool>());
    EXPECT_FALSE(summary["reproducible"].as<bool>());
    const YAML::Node digest = YAML::LoadFile((out / "record" / "digest.yaml").string());
    EXPECT_EQ(digest["topics"]["chain/state"]["samples"].as<int>(), 2000);
    EXPECT_GT(digest["topics"]["chain/meas"]["samples"].as<int>(), 0);
    EXPECT_NE(read_file(out / "clock.log").find("free-running"), std::string::npos) << read_file(out / "clock.log");
}
