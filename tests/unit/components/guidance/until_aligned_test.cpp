// Safe flight until aligned: only the altitude-type elevator targets change, to level flight through the air.
#include <gtest/gtest.h>

#include "guidance/model/until_aligned.hpp"

using namespace gdnav::guidance;
using gdnav::gnc::AileronMode;
using gdnav::gnc::ChannelTargets;
using gdnav::gnc::ElevatorMode;

namespace {

ChannelTargets mission(ElevatorMode m, double target) {
    ChannelTargets t;
    t.throttle_target = 30.3;
    t.elevator_mode = m;
    t.elevator_target = target;
    t.aileron_mode = AileronMode::bank;
    t.aileron_target = 0.349;
    t.rudder_target = 0.01;
    return t;
}

}  // namespace

TEST(UntilAligned, AltitudeTargetsBecomeLevelFlightThroughTheAir) {
    for (const ElevatorMode m : {ElevatorMode::pressure_altitude, ElevatorMode::altitude}) {
        const ChannelTargets t = until_aligned(mission(m, 2290.9));
        EXPECT_EQ(t.elevator_mode, ElevatorMode::air_path_angle);
        EXPECT_EQ(t.elevator_target, 0.0);
        // The other channels fly as the mission says.
        EXPECT_EQ(t.throttle_target, 30.3);
        EXPECT_EQ(t.aileron_mode, AileronMode::bank);
        EXPECT_EQ(t.aileron_target, 0.349);
        EXPECT_EQ(t.rudder_target, 0.01);
        EXPECT_TRUE(needs_altitude(m));
    }
}

TEST(UntilAligned, TargetsWithoutAnAltitudeEstimateAreKept) {
    for (const ElevatorMode m : {ElevatorMode::pitch, ElevatorMode::air_path_angle}) {
        const ChannelTargets t = until_aligned(mission(m, 0.02));
        EXPECT_EQ(t.elevator_mode, m);
        EXPECT_EQ(t.elevator_target, 0.02);
        EXPECT_FALSE(needs_altitude(m));
    }
}
