#include "measurements.hpp"

#include <cmath>

namespace gdnav::control {

LoopMeasurements measure(const ControlEstimates& est) {
    LoopMeasurements m;
    m.airspeed_mps = est.airspeed_mps;
    m.sideslip_rad = est.aos_rad;
    m.pressure_altitude_m = est.pressure_altitude_m;
    m.altitude_m = est.altitude_m;

    const math::Mat3 r_nb = est.q_nb.normalized().toRotationMatrix();
    const math::Euler body = math::euler_from_dcm(r_nb);
    m.heading_rad = body.yaw_rad;
    m.pitch_rad = body.pitch_rad;
    m.bank_rad = body.bank_rad;

    m.ground_bearing_rad = std::atan2(est.v_n_mps.y(), est.v_n_mps.x());

    const math::Euler air = math::euler_from_dcm(r_nb * math::dcm_body_from_wind(est.aoa_rad, est.aos_rad));
    m.air_bearing_rad = air.yaw_rad;
    m.air_path_angle_rad = air.pitch_rad;
    m.air_bank_rad = air.bank_rad;
    return m;
}

}  // namespace gdnav::control
