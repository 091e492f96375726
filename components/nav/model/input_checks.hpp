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

struct Range {
    double lo, hi;
};

constexpr double kPi = 3.141592653589793;
constexpr double kMaxSpecificForce_mps2 = 500.0;
constexpr double kMaxRate_rps = 35.0;
constexpr double kMaxMagField_nT = 5.0e5;
constexpr double kMaxGnssSpeed_mps = 500.0;
constexpr Range kTas_mps{-20.0, 350.0};
constexpr Range kVaneAngle_rad{-0.5 * kPi, 0.5 * kPi};
constexpr Range kPressure_Pa{1.0e3, 1.2e5};
constexpr Range kTemperature_K{150.0, 350.0};
constexpr Range kLat_rad{-0.5 * kPi, 0.5 * kPi};
constexpr Range kLon_rad{-2.0 * kPi, 2.0 * kPi};
constexpr Range kHeight_m{-1000.0, 1.0e5};

inline bool within(double v, Range r) { return std::isfinite(v) && v >= r.lo && v <= r.hi; }
inline bool within_abs(const Vec3& v, double hi) { return v.allFinite() && v.cwiseAbs().maxCoeff() <= hi; }

// Airspeed and vane angles: of an AirSample and of an AirDataEstimate.
template <class Air>
bool air_angles_ok(const Air& a) {
    return within(a.tas_mps, kTas_mps) && within(a.aoa_rad, kVaneAngle_rad) && within(a.aos_rad, kVaneAngle_rad);
}
// Position and velocity: of a GNSS fix and of a PositionEstimate.
template <class Pos>
bool position_ok(const Pos& p) {
    return within(p.lat_rad, kLat_rad) && within(p.lon_rad, kLon_rad) && within(p.h_m, kHeight_m) &&
           within_abs(p.v_n_mps, kMaxGnssSpeed_mps);
}

inline bool imu_ok(const ImuSample& s) {
    return within_abs(s.f_b_mps2, kMaxSpecificForce_mps2) && within_abs(s.w_b_rps, kMaxRate_rps);
}
inline bool mag_ok(const MagSample& s) { return within_abs(s.b_b_nT, kMaxMagField_nT); }
inline bool air_ok(const AirSample& s) { return air_angles_ok(s); }
inline bool atm_ok(const AtmSample& s) { return within(s.p_Pa, kPressure_Pa) && within(s.T_K, kTemperature_K); }
// Position and velocity of a fix (the caller checks fix_valid: a sample without a fix is not a rejection).
inline bool gnss_fix_ok(const GnssSample& s) { return position_ok(s); }
inline bool air_estimate_ok(const AirDataEstimate& e) {
    return air_angles_ok(e) && std::isfinite(e.Hp_m) && std::isfinite(e.dT_K) && std::isfinite(e.T_K) &&
           std::isfinite(e.roc_mps) && std::isfinite(e.tas_dot_mps2) && std::isfinite(e.aoa_dot_rps) &&
           std::isfinite(e.aos_dot_rps);
}
inline bool attitude_estimate_ok(const AttitudeEstimate& e) {
    const double n = e.q_nb.coeffs().norm();
    return e.q_nb.coeffs().allFinite() && n > 0.5 && n < 2.0 && within_abs(e.w_nb_b_rps, kMaxRate_rps);
}
// The fields of the previous PositionEstimate the attitude filter takes p_n from.
inline bool position_estimate_ok(const PositionEstimate& e) {
    return position_ok(e) && within_abs(e.wind_n_mps, kMaxGnssSpeed_mps) &&
           within_abs(e.acc_err_b_mps2, kMaxSpecificForce_mps2);
}

}  // namespace gdnav::nav::checks
