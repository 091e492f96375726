#pragma once
// control: GuidanceTargets + estimates (step k) -> ControlCommands (step k), applied by flight_physics at step k+1.
// Config: `autopilot: control/mugin_autopilot.yaml` (relative to config/).
#include "framework/registry.hpp"

namespace gdnav::control {
void register_control_component(framework::ComponentRegistry& reg);
}
