#pragma once
// Safe flight until the navigation is aligned (docs/navigation.md, "Safe flight until aligned").
//
// A truth-free start leaves the estimates unsettled for tens of seconds, and the pressure altitude of the air data
// filter can be tens of metres off before GNSS teaches it the pressure offset. An altitude hold closed on that
// estimate pushes the aircraft over or pulls it up; the vertical acceleration it causes is not in the attitude
// filter's model, and a filter with a truth-free covariance turns it into attitude error, which the autopilot then
// flies on. As a real autopilot does not engage its altitude hold on an unaligned INS, the elevator channel flies
// level through the air instead while the navigation is not aligned: an altitude-type target (pressure_altitude,
// altitude) becomes air_path_angle 0 (the flight-path angle through the air mass, from the attitude and the air
// data's angle of attack, no altitude estimate in the loop). The throttle (airspeed), aileron (bank, bearing,
// heading: the pattern's turns and straight legs) and rudder channels fly as the mission says. Once aligned the
// mission's own targets return, and the autopilot's outer-loop limit on the pitch target bounds the correction of
// the altitude drift meanwhile.
#include "gnc/modes.hpp"

namespace gdnav::guidance {

// The targets to fly while the navigation is not aligned, given the mission's.
[[nodiscard]] gnc::ChannelTargets until_aligned(const gnc::ChannelTargets& mission);

// True when the mission's elevator target needs an altitude estimate (the channel until_aligned changes).
[[nodiscard]] bool needs_altitude(gnc::ElevatorMode m);

}  // namespace gdnav::guidance
