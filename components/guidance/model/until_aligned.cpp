#include "until_aligned.hpp"

namespace gdnav::guidance {

bool needs_altitude(gnc::ElevatorMode m) {
    return m == gnc::ElevatorMode::pressure_altitude || m == gnc::ElevatorMode::altitude;
}

gnc::ChannelTargets until_aligned(const gnc::ChannelTargets& mission) {
    gnc::ChannelTargets t = mission;
    if (needs_altitude(t.elevator_mode)) {
        t.elevator_mode = gnc::ElevatorMode::air_path_angle;
        t.elevator_target = 0.0;
    }
    return t;
}

}  // namespace gdnav::guidance
