#pragma once
// guidance: AirDataEstimate + AttitudeEstimate + PositionEstimate (step k) -> GuidanceTargets (step k).
// Config: `mission: missions/<file>.yaml` (relative to config/) or an inline `mission:` mapping (same format).
#include "framework/registry.hpp"

namespace gdnav::guidance {
void register_guidance_component(framework::ComponentRegistry& reg);
}
