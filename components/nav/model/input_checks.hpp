#pragma once
// Sanity checks of the samples a navigation filter reads (docs/navigation.md, "Input checks"). Samples reach the
// filters over DDS, from the simulated sensors, from external members (a hardware-in-the-loop sensor, another team's
// filter) or through an injected fault, so a filter cannot assume they are finite or physical. Every filter checks
// each of its inputs on every step; a sample that fails is rejected: the filter skips the observation rows that
// sample feeds (or, for an estimate from another filter used as a model input, holds the last good one), counts the
// rejection per input, and its state never sees the value. A nominal sample passes every check, so runs with
// clean inputs are bit-identical to the filters without the checks.
//
// Bounds: far outside anything the airframe or a working sensor can produce, so they catch corrupt samples
// (non-finite values, unit or scaling slips, garbage) and never clip a real measurement.
//   specific force  |f_i| <= 500 m/s^2 per axis    (~50 g; MEMS IMU ranges are 8..40 g)
//   angular rate    |w_i| <= 35 rad/s per axis     (~2000 deg/s, the widest MEMS gyro range)
//   magnetic field  |B_i| <= 5e5 nT per axis       (Earth field <= 6.6e4 nT; hard iron of a small UAV ~ 1e3 nT)
//   true airspeed   -20 <= v_tas <= 350 m/s         (subsonic; a Pitot reads slightly negative near zero speed)
//   AOA, AOS vanes  |angle| <= pi/2
//   static pressure 1e3 <= p <= 1.2e5 Pa            (Hp ~ 31 km .. below the Dead Sea)
//   air temperature 150 <= T <= 350 K
//   GNSS fix        |lat| <= pi/2, |lon| <= 2 pi, -1000 <= h <= 1e5 m, |v_i| <= 500 m/s
//   estimates from the other filters (AirDataEstimate, AttitudeEstimate, PositionEstimate used as model inputs):
//                   finite, |q| within 0.5..2 (renormalised by the reader), the air data bounds above.
#include <cmath>

#include "nav_types.hpp"

namespace gdnav::nav::checks {

constexpr double kMaxSpecificForce_mps2 = 500.0;
constexpr double kMaxRate_rps = 35.0;
constexpr double kMaxMagField_nT = 5.0e5;
constexpr double kMinTas_mps = -20.0;
constexpr double kMaxTas_mps = 350.0;
constexpr double kMaxVaneAngle_rad = 1.5707963267948966;
constexpr double kMinPressure_Pa = 1.0e3;
constexpr double kMaxPressure_Pa = 1.2e5;
constexpr double kMinTemperature_K = 150.0;
constexpr double kMaxTemperature_K = 350.0;
constexpr double kMinHeight_m = -1000.0;
constexpr double kMaxHeight_m = 1.0e5;
constexpr double kMaxGnssSpeed_mps = 500.0;

inline bool within(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }
inline bool within_abs(const Vec3& v, double hi) { return v.allFinite() && v.cwiseAbs().maxCoeff() <= hi; }

inline bool imu_ok(const ImuSample& s) {
    return within_abs(s.f_b_mps2, kMaxSpecificForce_mps2) && within_abs(s.w_b_rps, kMaxRate_rps);
}
inline bool mag_ok(const MagSample& s) { return within_abs(s.b_b_nT, kMaxMagField_nT); }
inline bool air_ok(const AirSample& s) {
    return within(s.tas_mps, kMinTas_mps, kMaxTas_mps) && within(s.aoa_rad, -kMaxVaneAngle_rad, kMaxVaneAngle_rad) &&
           within(s.aos_rad, -kMaxVaneAngle_rad, kMaxVaneAngle_rad);
}
inline bool atm_ok(const AtmSample& s) {
    return within(s.p_Pa, kMinPressure_Pa, kMaxPressure_Pa) && within(s.T_K, kMinTemperature_K, kMaxTemperature_K);
}
// Position and velocity of a fix (the caller checks fix_valid: a sample without a fix is not a rejection).
inline bool gnss_fix_ok(const GnssSample& s) {
    constexpr double kPi = 3.141592653589793;
    return within(s.lat_rad, -0.5 * kPi, 0.5 * kPi) && within(s.lon_rad, -2.0 * kPi, 2.0 * kPi) &&
           within(s.h_m, kMinHeight_m, kMaxHeight_m) && within_abs(s.v_n_mps, kMaxGnssSpeed_mps);
}
inline bool air_estimate_ok(const AirDataEstimate& e) {
    return within(e.tas_mps, kMinTas_mps, kMaxTas_mps) && within(e.aoa_rad, -kMaxVaneAngle_rad, kMaxVaneAngle_rad) &&
           within(e.aos_rad, -kMaxVaneAngle_rad, kMaxVaneAngle_rad) && std::isfinite(e.Hp_m) &&
           std::isfinite(e.dT_K) && std::isfinite(e.T_K) && std::isfinite(e.roc_mps) &&
           std::isfinite(e.tas_dot_mps2) && std::isfinite(e.aoa_dot_rps) && std::isfinite(e.aos_dot_rps);
}
inline bool attitude_estimate_ok(const AttitudeEstimate& e) {
    const double n = e.q_nb.coeffs().norm();
    return e.q_nb.coeffs().allFinite() && n > 0.5 && n < 2.0 && within_abs(e.w_nb_b_rps, kMaxRate_rps);
}
// The fields of the previous PositionEstimate the attitude filter takes p_n from.
inline bool position_estimate_ok(const PositionEstimate& e) {
    constexpr double kPi = 3.141592653589793;
    return within(e.lat_rad, -0.5 * kPi, 0.5 * kPi) && within(e.lon_rad, -2.0 * kPi, 2.0 * kPi) &&
           within(e.h_m, kMinHeight_m, kMaxHeight_m) && within_abs(e.v_n_mps, kMaxGnssSpeed_mps) &&
           within_abs(e.wind_n_mps, kMaxGnssSpeed_mps) && within_abs(e.acc_err_b_mps2, kMaxSpecificForce_mps2);
}

}  // namespace gdnav::nav::checks
