// Allan-deviation checks of the inertial triads on long static records (w_ib = 0, f_ib = 0, so the output is
// bias offset + bias drift + white noise). Expected values are the textbook Allan results for the configured
// densities (IEEE Std 952): white rate noise sigma_v -> ADEV(tau) = sigma_v / sqrt(tau); rate random walk
// sigma_u -> ADEV(tau) = sigma_u sqrt(tau / 3) (the discrete-time correction 1 + 1/(2 m^2) is < 1e-4 here).
// Confidence: equivalent degrees of freedom of the overlapping estimator (NIST SP 1065, table 5):
//   white noise  edf ~ 3 (N - 1) / (2 m);   random walk  edf ~ (N - 2) / m;
// relative standard error of an ADEV value ~ 1 / sqrt(2 edf).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "allan.hpp"
#include "sensor_test_support.hpp"
#include "sensors/model/inertial.hpp"

namespace gdnav::sensors {
namespace {

using test::allan_deviation;

constexpr std::size_t kSteps = 1u << 20;  // 1,048,576 samples = 2.9 h at 100 Hz

struct StaticRecord {
    std::vector<double> gyr[3], acc[3];        // measured outputs
    double gyr_drift_max[3]{}, acc_drift_max[3]{};  // max |b_drift| per axis
};

StaticRecord record(const InertialParams& p, std::uint64_t seed) {
    InertialSensors imu;
    imu.configure(p, rnd::Stream::derive(seed, 0, "sensors_inertial"));
    StaticRecord r;
    for (int i = 0; i < 3; ++i) {
        r.gyr[i].reserve(kSteps);
        r.acc[i].reserve(kSteps);
    }
    InertialTruth truth;
    truth.mass_kg = p.platform.mass_full_kg;
    for (std::size_t k = 0; k < kSteps; ++k) {
        const ImuMeasurement m = imu.measure(k, static_cast<double>(k) * p.dt_s, truth);
        const Vec3 dg = imu.gyr().drift();
        const Vec3 da = imu.acc().drift();
        for (int i = 0; i < 3; ++i) {
            r.gyr[i].push_back(m.w_b_rps[i]);
            r.acc[i].push_back(m.f_b_mps2[i]);
            r.gyr_drift_max[i] = std::max(r.gyr_drift_max[i], std::abs(dg[i]));
            r.acc_drift_max[i] = std::max(r.acc_drift_max[i], std::abs(da[i]));
        }
    }
    return r;
}

// Static record (w = 0, f = 0): no scale or misalignment effects. The IMU is put at the CG with a perfectly
// known position so the lever-arm compensation (which differentiates the gyro output, see
// InertialEquations.LeverArmCompensationInjectsDifferentiatedGyroNoise) adds nothing: the record is the
// triads' own error model.
InertialParams static_params() {
    InertialParams p = test::baseline_suite().inertial;
    p.platform.imu_position_m = p.platform.cg_full_m;
    p.platform.cg_empty_m = p.platform.cg_full_m;
    p.platform.imu_position_error_m = 0.0;
    return p;
}

// The baseline record (N = 100) is shared by the tests that only read it.
const StaticRecord& baseline_record() {
    static const StaticRecord r = record(static_params(), 11);
    return r;
}

TEST(InertialAllan, HelperMatchesHandComputation) {
    // Alternating +1, -1 (tau0 = 1 s): clusters of 1 differ by +-2 -> AVAR = (1/2) 4 = 2; clusters of 2 have
    // mean 0 -> ADEV 0.
    std::vector<double> y;
    for (int i = 0; i < 1000; ++i) y.push_back(i % 2 == 0 ? 1.0 : -1.0);
    EXPECT_NEAR(allan_deviation(y, 1.0, 1), std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(allan_deviation(y, 1.0, 2), 0.0, 1e-12);
}

void record_ratio(const std::string& name, double value) {
    ::testing::Test::RecordProperty(name, std::to_string(value));
}

TEST(InertialAllan, WhiteNoiseDensityAtOneSecond) {
    const InertialParams p = static_params();
    const StaticRecord& r = baseline_record();
    const std::size_t m = 100;  // tau = 1 s
    // edf = 1.5 * 1.05e6 / 100 = 1.6e4 -> ADEV standard error 0.56 %; 3 % is > 5 standard errors (the brief asks
    // for 10 %). The drift (band-limited walk) adds sigma_u^2 tau / 3 at most: 3.6e-4 of the gyro variance.
    for (int i = 0; i < 3; ++i) {
        const double want_g = std::sqrt(p.gyr.system_noise * p.gyr.system_noise + p.gyr.bias_drift * p.gyr.bias_drift / 3.0);
        const double want_a = std::sqrt(p.acc.system_noise * p.acc.system_noise + p.acc.bias_drift * p.acc.bias_drift / 3.0);
        const double rg = allan_deviation(r.gyr[i], p.dt_s, m) / want_g;
        const double ra = allan_deviation(r.acc[i], p.dt_s, m) / want_a;
        record_ratio("gyr_adev1s_ratio_axis" + std::to_string(i), rg);
        record_ratio("acc_adev1s_ratio_axis" + std::to_string(i), ra);
        EXPECT_NEAR(rg, 1.0, 0.03) << "gyro axis " << i;
        EXPECT_NEAR(ra, 1.0, 0.03) << "acc axis " << i;
    }
    // Same at tau = 0.1 s (m = 10; edf 1.6e5, standard error 0.18 %): the 1/sqrt(tau) law, not just one point.
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(allan_deviation(r.gyr[i], p.dt_s, 10) * std::sqrt(0.1) / p.gyr.system_noise, 1.0, 0.02);
        EXPECT_NEAR(allan_deviation(r.acc[i], p.dt_s, 10) * std::sqrt(0.1) / p.acc.system_noise, 1.0, 0.02);
    }
}

TEST(InertialAllan, BiasDriftRandomWalkSlope) {
    // Drift-only triads (sigma_v = 0) and a band so wide it is never reached (1e6 steps; a walk of 1e6 steps
    // spreads ~1e3 steps), so the record is the unbounded random walk of density sigma_u.
    InertialParams p = static_params();
    p.gyr.system_noise = 0.0;
    p.acc.system_noise = 0.0;
    p.bias_drift_band = 1.0e6;
    const StaticRecord r = record(p, 12);
    // tau = 1 s: edf ~ 1e4, standard error 0.7 %; tau = 10 s: edf ~ 1e3, standard error 2.2 % -> 10 % is 4.5 s.e.
    for (const std::size_t m : {std::size_t{100}, std::size_t{1000}}) {
        const double tau = static_cast<double>(m) * p.dt_s;
        for (int i = 0; i < 3; ++i) {
            const double rg = allan_deviation(r.gyr[i], p.dt_s, m) / (p.gyr.bias_drift * std::sqrt(tau / 3.0));
            const double ra = allan_deviation(r.acc[i], p.dt_s, m) / (p.acc.bias_drift * std::sqrt(tau / 3.0));
            record_ratio("gyr_rw_ratio_tau" + std::to_string(m) + "_axis" + std::to_string(i), rg);
            record_ratio("acc_rw_ratio_tau" + std::to_string(m) + "_axis" + std::to_string(i), ra);
            EXPECT_NEAR(rg, 1.0, 0.10) << "gyro axis " << i << " tau " << tau;
            EXPECT_NEAR(ra, 1.0, 0.10) << "acc axis " << i << " tau " << tau;
        }
    }
}

TEST(InertialAllan, DriftStaysInsideItsBandAndUsesIt) {
    for (const double band : {100.0, 300.0}) {
        InertialParams p = static_params();
        p.bias_drift_band = band;
        StaticRecord wide;
        if (band != 100.0) wide = record(p, 13);
        const StaticRecord& r = band == 100.0 ? baseline_record() : wide;
        const double gyr_band = band * p.gyr.bias_drift * std::sqrt(p.dt_s);
        const double acc_band = band * p.acc.bias_drift * std::sqrt(p.dt_s);
        for (int i = 0; i < 3; ++i) {
            EXPECT_LE(r.gyr_drift_max[i], gyr_band) << "band " << band << " axis " << i;
            EXPECT_LE(r.acc_drift_max[i], acc_band) << "band " << band << " axis " << i;
            // 1e6 steps of an unbounded walk spread ~1000 steps, so the walk must come close to both limits.
            EXPECT_GT(r.gyr_drift_max[i], 0.9 * gyr_band);
            EXPECT_GT(r.acc_drift_max[i], 0.9 * acc_band);
        }
    }
}

TEST(InertialAllan, BandBoundsLongTermDrift) {
    // With N = 100 the walk cannot wander: at tau = 1000 s the unbounded walk would give sigma_u sqrt(tau/3);
    // the bounded one stays within +-10 sigma_u (in units of sigma_u s^0.5), so its ADEV is several times smaller.
    const InertialParams p = static_params();
    const StaticRecord& r = baseline_record();
    const double tau = 1000.0;
    for (int i = 0; i < 3; ++i) {
        const double unbounded = p.gyr.bias_drift * std::sqrt(tau / 3.0);
        const double ratio = allan_deviation(r.gyr[i], p.dt_s, 100000) / unbounded;
        record_ratio("gyr_adev1000s_over_unbounded_axis" + std::to_string(i), ratio);
        EXPECT_LT(ratio, 0.5) << "axis " << i;
    }
}

}  // namespace
}  // namespace gdnav::sensors
