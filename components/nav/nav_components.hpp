#pragma once
// The navigation filter components (models in nav/model, plain C++), one file each (nav_air.cpp, nav_att.cpp,
// nav_pos.cpp; what they share in nav_files.hpp):
//   nav_air  AirSample + AtmSample (k)                                       -> AirDataEstimate (k)
//   nav_att  ImuSample + MagSample (k), PositionEstimate (k-1, p_n source)   -> AttitudeEstimate (k)
//            (+ AirDataEstimate and GnssSample of step 0 for its initialisation)
//   nav_pos  ImuSample + GnssSample + AirDataEstimate + AttitudeEstimate (k) -> PositionEstimate (k)
// Config sections: `tuning: nav/tuning.yaml`, `variant: nav/variants/baseline.yaml` (relative to config/), and
// optionally `init_mode: measurements | alignment` (overrides the tuning file). In alignment mode the filters start
// from the pre-flight fine alignment the sensors publish with their samples (ImuSample / MagSample align_*: attitude,
// E_gyr, E_acc, E_mag, B_dev and their sigmas; docs/navigation.md, "Initialisation"). No navigation component reads
// the truth.
// nav_pos enters GNSS-denied mode when no valid fix arrived for 1.5 s of simulated time, at the step the clock
// declares the GNSS publisher dead, or when 5 fixes in a row fail its chi-square gate (source untrusted), and
// publishes "GNSS lost: <reason>" on ComponentStatus; it returns to GNSS-aided after 5 consecutive consistent fixes
// and publishes "GNSS re-acquired". Every filter rejects non-finite or out-of-range samples; the components publish
// the rejection counts on ComponentStatus (MODE) and log an end-of-run summary (docs/navigation.md, "Input checks").
// nav_att optionally runs the joint GNSS/INS estimator (in-flight alignment, or the variants keep_gnss_calibration
// and gnss_calibration_handover)
// and publishes it on gdnav/NavHandover, which nav_pos follows (docs/navigation.md, "In-flight alignment").
#include "framework/registry.hpp"

namespace gdnav::nav {
void register_nav_components(framework::ComponentRegistry& reg);
}
