#pragma once
// The five sensor-group components. Each turns Truth(k) into its measurement topic with the error models of
// sensors/model (one random stream per component, derived from seed, run index and component name).
//
//   sensors_inertial     Truth -> ImuSample    gyroscopes + accelerometers (+ IMU mounting, lever arm)
//   sensors_magnetic     Truth -> MagSample    magnetometers
//   sensors_air          Truth -> AirSample    Pitot TAS, AOA and AOS vanes
//   sensors_atmospheric  Truth -> AtmSample    static pressure, outside air temperature
//   sensors_gnss         Truth -> GnssSample   1 Hz fixes until the signal loss time, fix_valid otherwise false
//
// Config section of each: `suite: sensors/suite.yaml` (relative to config/; grades named in the suite) and
// optionally `grade: <name>` to override the suite's grade for this group (inertial: `gyr_grade`, `acc_grade`,
// `bias_drift_band`), and for GNSS `loss_time_s` (t_GNSS) or `never_lost: true`. Step time and t0 come from the run.
#include "framework/registry.hpp"

namespace gdnav::sensors {

void register_sensor_components(framework::ComponentRegistry& reg);

}  // namespace gdnav::sensors
