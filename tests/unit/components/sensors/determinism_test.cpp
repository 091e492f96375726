// Reproducibility: the same stream seed gives bit-identical measurements, another seed different ones, and each
// sensor's draws are independent of the other sensors' settings (own sub-streams).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "sensor_test_support.hpp"
#include "sensors/model/air_data.hpp"
#include "sensors/model/gnss.hpp"
#include "sensors/model/inertial.hpp"
#include "sensors/model/magnetic.hpp"

namespace gdnav::sensors {
namespace {

constexpr std::uint64_t kSteps = 3000;  // 30 s: 31 GNSS fixes

// A smoothly varying truth so that every term of every model is exercised.
struct Truths {
    InertialTruth imu;
    MagTruth mag;
    AirTruth air;
    AtmTruth atm;
    GnssTruth gnss;
};
Truths truth_at(std::uint64_t k) {
    const double t = 0.01 * static_cast<double>(k);
    Truths x;
    x.imu.f_ib_b_mps2 = {0.3 * std::sin(t), 0.1 * std::cos(2 * t), -9.7 + 0.2 * std::sin(3 * t)};
    x.imu.w_ib_b_rps = {0.2 * std::sin(0.5 * t), 0.05 * std::cos(t), 0.1 * std::sin(0.2 * t)};
    x.imu.dw_ib_b_rps2 = {0.1 * std::cos(0.5 * t), -0.05 * std::sin(t), 0.02 * std::cos(0.2 * t)};
    x.imu.mass_kg = 19.7 - 1e-4 * t;
    x.mag.q_nb = math::quat_from_euler({0.3 * t, 0.05, -0.1});
    x.mag.b_n_nT = {17455.7, -764.6, 52192.7};
    x.air = {25.0 + std::sin(t), 0.05, 0.01 * std::cos(t)};
    x.atm = {70000.0 - t, 268.0};
    x.gnss = {math::deg2rad(270.0), math::deg2rad(45.0) + 1e-6 * t, 3000.0, {25.0, 1.0, 0.0}};
    return x;
}

// Every output double of every group, in a fixed order.
std::vector<double> run(const SensorSuiteParams& s, std::uint64_t seed) {
    InertialSensors imu;
    Magnetometers mag;
    AirDataSensors air;
    AtmosphericSensors atm;
    GnssReceiver gnss;
    imu.configure(s.inertial, rnd::Stream::derive(seed, 0, "sensors_inertial"));
    mag.configure(s.mag, rnd::Stream::derive(seed, 0, "sensors_magnetic"));
    air.configure(s.air, rnd::Stream::derive(seed, 0, "sensors_air"));
    atm.configure(s.atm, rnd::Stream::derive(seed, 0, "sensors_atmospheric"));
    gnss.configure(s.gnss, rnd::Stream::derive(seed, 0, "sensors_gnss"));
    std::vector<double> out;
    for (std::uint64_t k = 0; k < kSteps; ++k) {
        const Truths x = truth_at(k);
        const double t = s.gnss.t0_s + static_cast<double>(k) * 0.01;
        const ImuMeasurement i = imu.measure(k, t, x.imu);
        const MagMeasurement m = mag.measure(k, t, x.mag);
        const AirMeasurement a = air.measure(k, t, x.air);
        const AtmMeasurement p = atm.measure(k, t, x.atm);
        const GnssMeasurement g = gnss.measure(k, t, x.gnss);
        for (int j = 0; j < 3; ++j) {
            out.push_back(i.w_b_rps[j]);   // index 0, 1, 2 of each 17-value block: gyroscopes
            out.push_back(i.f_b_mps2[j]);
            out.push_back(m.b_b_nT[j]);
        }
        out.insert(out.end(), {a.tas_mps, a.aoa_rad, a.aos_rad, p.p_Pa, p.T_K, g.lat_rad, g.lon_rad, g.h_m});
    }
    return out;
}

bool bit_identical(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(SensorDeterminism, SameSeedSameBitsOtherSeedOtherValues) {
    const SensorSuiteParams s = test::baseline_suite();
    const std::vector<double> a = run(s, 42);
    const std::vector<double> b = run(s, 42);
    const std::vector<double> c = run(s, 43);
    EXPECT_TRUE(bit_identical(a, b));
    ASSERT_EQ(a.size(), c.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.size(); ++i) differing += (a[i] != c[i]) ? 1u : 0u;
    // Every output differs (the GNSS values held between fixes differ too: they are other fixes).
    EXPECT_EQ(differing, a.size());
}

TEST(SensorDeterminism, ChangingOneSensorLeavesTheOthersDrawsAlone) {
    // A larger accelerometer bias offset: gyroscope outputs bit-identical (own "gyr" sub-stream), accelerometer
    // outputs all different.
    const SensorSuiteParams base = test::baseline_suite();
    SensorSuiteParams acc = base;
    acc.inertial.acc.bias_offset *= 2.0;
    const std::vector<double> a = run(base, 7);
    const std::vector<double> b = run(acc, 7);
    for (std::uint64_t k = 0; k < kSteps; ++k) {
        for (int j = 0; j < 3; ++j) {
            ASSERT_EQ(a[17 * k + 3 * j], b[17 * k + 3 * j]) << "gyro changed at step " << k;
            ASSERT_NE(a[17 * k + 3 * j + 1], b[17 * k + 3 * j + 1]) << "accelerometer unchanged at step " << k;
        }
    }
    // A noisier Pitot tube leaves the vanes untouched.
    AirParams p = base.air;
    AirParams q = base.air;
    q.grade.tas_mps.noise *= 3.0;
    AirDataSensors x, y;
    x.configure(p, rnd::Stream(99));
    y.configure(q, rnd::Stream(99));
    for (std::uint64_t k = 0; k < 1000; ++k) {
        const AirMeasurement mx = x.measure(k, 0.0, {25.0, 0.05, 0.0});
        const AirMeasurement my = y.measure(k, 0.0, {25.0, 0.05, 0.0});
        ASSERT_EQ(mx.aoa_rad, my.aoa_rad);
        ASSERT_EQ(mx.aos_rad, my.aos_rad);
        ASSERT_NE(mx.tas_mps, my.tas_mps);
    }
}

}  // namespace
}  // namespace gdnav::sensors
