#include "sensors/model/air_data.hpp"

namespace gdnav::sensors {

void ScalarSensor::configure(const ScalarGrade& grade, rnd::Stream stream) {
    grade_ = grade;
    rnd::Stream off = stream.child("offset");
    offset_ = grade.bias_offset * off.normal();
    noise_ = stream.child("noise");
}

void AirDataSensors::configure(const AirParams& params, rnd::Stream stream) {
    params_ = params;
    tas_.configure(params.grade.tas_mps, stream.child("tas"));
    aoa_.configure(params.grade.aoa_rad, stream.child("aoa"));
    aos_.configure(params.grade.aos_rad, stream.child("aos"));
}

AirMeasurement AirDataSensors::measure(std::uint64_t k, double t_s, const AirTruth& truth) {
    return {.step = k,
            .t_s = t_s,
            .tas_mps = tas_.measure(truth.tas_mps),
            .aoa_rad = aoa_.measure(truth.aoa_rad),
            .aos_rad = aos_.measure(truth.aos_rad)};
}

void AtmosphericSensors::configure(const AtmParams& params, rnd::Stream stream) {
    params_ = params;
    osp_.configure(params.grade.p_Pa, stream.child("osp"));
    oat_.configure(params.grade.T_K, stream.child("oat"));
}

AtmMeasurement AtmosphericSensors::measure(std::uint64_t k, double t_s, const AtmTruth& truth) {
    return {.step = k, .t_s = t_s, .p_Pa = osp_.measure(truth.p_Pa), .T_K = oat_.measure(truth.T_K)};
}

}  // namespace gdnav::sensors
