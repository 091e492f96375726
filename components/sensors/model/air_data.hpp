#pragma once
// Air data sensors (docs/sensors.md, "Air data and atmospheric"; paper, "Sensors"): Pitot tube (TAS),
// angle-of-attack and sideslip vanes, barometer (outside static pressure) and thermometer (outside air temperature).
// Each one only has
//
//   y~ = y + B0 nu_0 + sigma nu_k        nu_0 ~ N(0,1) once per run, nu_k ~ N(0,1) per sample,
//
// where sigma is the per-sample standard deviation (no sqrt(dt) scaling, unlike the inertial triads).
// Streams: each sensor uses the group stream's child named after it ("tas", "aoa", "aos"; "osp", "oat"), with
// children "offset" and "noise".
#include <cstdint>

#include "random/stream.hpp"
#include "sensors/model/sensor_io.hpp"
#include "sensors/model/suite.hpp"

namespace gdnav::sensors {

// One offset-plus-noise sensor.
class ScalarSensor {
public:
    void configure(const ScalarGrade& grade, rnd::Stream stream);
    double measure(double truth) { return truth + offset_ + grade_.noise * noise_.normal(); }
    [[nodiscard]] double offset() const { return offset_; }
    [[nodiscard]] const ScalarGrade& grade() const { return grade_; }

private:
    ScalarGrade grade_;
    double offset_{0.0};
    rnd::Stream noise_;
};

// Pitot tube + vanes. Inputs: AirTruth (tas, aoa, aos). Outputs: AirMeasurement.
class AirDataSensors {
public:
    void configure(const AirParams& params, rnd::Stream stream);
    AirMeasurement measure(std::uint64_t k, double t_s, const AirTruth& truth);

    [[nodiscard]] const AirParams& params() const { return params_; }
    [[nodiscard]] const ScalarSensor& tas() const { return tas_; }
    [[nodiscard]] const ScalarSensor& aoa() const { return aoa_; }
    [[nodiscard]] const ScalarSensor& aos() const { return aos_; }

private:
    AirParams params_;
    ScalarSensor tas_, aoa_, aos_;
};

// Barometer + thermometer. Inputs: AtmTruth (p, T). Outputs: AtmMeasurement.
class AtmosphericSensors {
public:
    void configure(const AtmParams& params, rnd::Stream stream);
    AtmMeasurement measure(std::uint64_t k, double t_s, const AtmTruth& truth);

    [[nodiscard]] const AtmParams& params() const { return params_; }
    [[nodiscard]] const ScalarSensor& osp() const { return osp_; }
    [[nodiscard]] const ScalarSensor& oat() const { return oat_; }

private:
    AtmParams params_;
    ScalarSensor osp_, oat_;
};

}  // namespace gdnav::sensors
