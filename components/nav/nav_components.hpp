#pragma once
// The navigation filter components (models in nav/model, plain C++):
//   nav_air  AirSample + AtmSample (k)                                       -> AirDataEstimate (k)
//   nav_att  ImuSample + MagSample (k), PositionEstimate (k-1, p_n source)   -> AttitudeEstimate (k)
//            (+ AirDataEstimate and GnssSample of step 0 for its initialisation)
//   nav_pos  ImuSample + GnssSample + AirDataEstimate + AttitudeEstimate (k) -> PositionEstimate (k)
// Config sections: `tuning: nav/tuning.yaml`, `variant: nav/variants/baseline.yaml` (relative to config/), and
// optionally `init_mode: measurements | reference` (overrides the tuning file). In reference mode the filters start
// like the reference's fine alignment (models-nav.md §6): true attitude (Truth of step 0, nav_att only) and the
// sensors' calibration errors (ImuSample/MagSample e_* fields of step 0) with the reference's small random errors.
// nav_pos enters GNSS-denied mode when no valid fix arrived for 1.5 s of simulated time or at the step the clock
// declares the GNSS publisher dead, and publishes "GNSS lost" on ComponentStatus.
#include "runtime/registry.hpp"

namespace gdnav::nav {
void register_nav_components(runtime::ComponentRegistry& reg);
}
