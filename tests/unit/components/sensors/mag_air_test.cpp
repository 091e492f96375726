// Magnetometer, Pitot/vane and barometer/thermometer models: per-run draws over many runs, per-sample noise over
// long records, and the magnetometer frame transformation by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sensor_test_support.hpp"
#include "sensors/model/air_data.hpp"
#include "sensors/model/magnetic.hpp"

namespace gdnav::sensors {
namespace {

using test::rms;
using test::stddev;

constexpr int kRuns = 2000;
constexpr int kSamples = 40000;

TEST(Magnetometers, RunToRunSigmas) {
    const MagParams p = test::baseline_suite().mag;
    std::vector<double> hi, off, diag, cross;
    for (int run = 0; run < kRuns; ++run) {
        Magnetometers mag;
        mag.configure(p, rnd::Stream::derive(9, static_cast<std::uint64_t>(run), "sensors_magnetic"));
        for (int i = 0; i < 3; ++i) {
            hi.push_back(mag.hard_iron_nT()[i]);
            off.push_back(mag.offset_nT()[i]);
            for (int j = 0; j < 3; ++j) (i == j ? diag : cross).push_back(mag.scale_cross()(i, j));
        }
    }
    // RMS standard error 1/sqrt(2n): n = 6000 -> 0.9 %, n = 12000 -> 0.65 %; tolerance 10 % (brief).
    EXPECT_NEAR(rms(hi) / 175.0, 1.0, 0.10);   // paper: hard iron 1.75e2 nT
    EXPECT_NEAR(rms(off) / 500.0, 1.0, 0.10);  // paper: bias offset 5.00e2 nT
    EXPECT_NEAR(rms(diag) / 7.50e-4, 1.0, 0.10);
    EXPECT_NEAR(rms(cross) / 9.16e-4, 1.0, 0.10);
    // Hard iron and offset are independent draws (their sum has sigma sqrt(175^2 + 500^2)), not one draw scaled.
    std::vector<double> corr;
    for (std::size_t i = 0; i < hi.size(); ++i) corr.push_back(hi[i] * off[i]);
    EXPECT_LT(std::abs(test::mean(corr)) / (175.0 * 500.0), 4.0 / std::sqrt(static_cast<double>(hi.size())));
}

TEST(Magnetometers, BodyFrameFieldAndNoise) {
    // Error-free grade except the white noise. Yaw 90 deg: body x points East, body y points South, so the NED
    // field (20000, 0, 45000) nT reads (0, -20000, 45000) nT in B.
    MagParams p = test::baseline_suite().mag;
    const double sigma_v = p.grade.system_noise_nT_rts;
    p.grade = MagGrade{};
    Magnetometers clean;
    clean.configure(p, rnd::Stream(3));
    MagTruth t;
    t.q_nb = math::quat_from_euler({math::deg2rad(90.0), 0.0, 0.0});
    t.b_n_nT = {20000.0, 0.0, 45000.0};
    const MagMeasurement m0 = clean.measure(0, 0.0, t);
    EXPECT_NEAR(m0.b_b_nT.x(), 0.0, 1e-9);
    EXPECT_NEAR(m0.b_b_nT.y(), -20000.0, 1e-9);
    EXPECT_NEAR(m0.b_b_nT.z(), 45000.0, 1e-9);

    p.grade.system_noise_nT_rts = sigma_v;
    Magnetometers noisy;
    noisy.configure(p, rnd::Stream(4));
    std::vector<double> e[3];
    for (int k = 0; k < kSamples; ++k) {
        const MagMeasurement m = noisy.measure(static_cast<std::uint64_t>(k), 0.0, t);
        for (int i = 0; i < 3; ++i) e[i].push_back(m.b_b_nT[i] - m0.b_b_nT[i]);
    }
    // 5 nT s^0.5 at dt = 0.01 s -> 50 nT per sample (reference 1.4). n = 40000: s.e. 0.35 %; tolerance 5 %.
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(rms(e[i]) / 50.0, 1.0, 0.05) << "axis " << i;
    EXPECT_NEAR(noisy.noise_nT(), 50.0, 1e-9);
}

TEST(AirData, PerSampleNoiseAndRunToRunOffsets) {
    const AirParams p = test::baseline_suite().air;
    const double deg = math::kDeg;
    // Per-sample noise: one long record at constant truth; the sample std removes the run's offset.
    AirDataSensors air;
    air.configure(p, rnd::Stream::derive(1, 0, "sensors_air"));
    const AirTruth truth{25.0, math::deg2rad(3.0), math::deg2rad(-1.0)};
    std::vector<double> tas, aoa, aos;
    for (int k = 0; k < kSamples; ++k) {
        const AirMeasurement m = air.measure(static_cast<std::uint64_t>(k), 0.0, truth);
        tas.push_back(m.tas_mps);
        aoa.push_back(m.aoa_rad);
        aos.push_back(m.aos_rad);
    }
    // Paper baseline: 0.333 m/s, 0.333 deg, 0.333 deg. n = 40000: s.e. of the std 0.35 %; tolerance 5 % (brief).
    EXPECT_NEAR(stddev(tas) / 0.333, 1.0, 0.05);
    EXPECT_NEAR(stddev(aoa) / (0.333 * deg), 1.0, 0.05);
    EXPECT_NEAR(stddev(aos) / (0.333 * deg), 1.0, 0.05);
    // The record mean is truth + offset: offset known to sigma/sqrt(n) = 0.5 % of sigma.
    EXPECT_NEAR(test::mean(tas) - truth.tas_mps, air.tas().offset(), 5.0 * 0.333 / std::sqrt(kSamples));

    std::vector<double> o_tas, o_aoa, o_aos;
    for (int run = 0; run < kRuns; ++run) {
        AirDataSensors a;
        a.configure(p, rnd::Stream::derive(2, static_cast<std::uint64_t>(run), "sensors_air"));
        o_tas.push_back(a.tas().offset());
        o_aoa.push_back(a.aoa().offset());
        o_aos.push_back(a.aos().offset());
    }
    // n = 2000 runs: s.e. 1.6 %; tolerance 10 %.
    EXPECT_NEAR(rms(o_tas) / 0.333, 1.0, 0.10);
    EXPECT_NEAR(rms(o_aoa) / (0.333 * deg), 1.0, 0.10);
    EXPECT_NEAR(rms(o_aos) / (0.333 * deg), 1.0, 0.10);
}

TEST(Atmospheric, PerSampleNoiseAndRunToRunOffsets) {
    const AtmParams p = test::baseline_suite().atm;
    AtmosphericSensors atm;
    atm.configure(p, rnd::Stream::derive(1, 0, "sensors_atmospheric"));
    const AtmTruth truth{70108.0, 268.66};
    std::vector<double> pr, te;
    for (int k = 0; k < kSamples; ++k) {
        const AtmMeasurement m = atm.measure(static_cast<std::uint64_t>(k), 0.0, truth);
        pr.push_back(m.p_Pa);
        te.push_back(m.T_K);
    }
    // Paper baseline: 100 Pa and 0.05 K per sample. n = 40000: s.e. 0.35 %; tolerance 5 %.
    EXPECT_NEAR(stddev(pr) / 100.0, 1.0, 0.05);
    EXPECT_NEAR(stddev(te) / 0.05, 1.0, 0.05);

    std::vector<double> o_p, o_t;
    for (int run = 0; run < kRuns; ++run) {
        AtmosphericSensors a;
        a.configure(p, rnd::Stream::derive(2, static_cast<std::uint64_t>(run), "sensors_atmospheric"));
        o_p.push_back(a.osp().offset());
        o_t.push_back(a.oat().offset());
    }
    EXPECT_NEAR(rms(o_p) / 100.0, 1.0, 0.10);
    EXPECT_NEAR(rms(o_t) / 0.05, 1.0, 0.10);
}

TEST(AirData, OffsetIsConstantWithinARun) {
    AirParams p = test::baseline_suite().air;
    p.grade.tas_mps.noise = 0.0;
    AirDataSensors air;
    air.configure(p, rnd::Stream(8));
    const double first = air.measure(0, 0.0, {30.0, 0.0, 0.0}).tas_mps;
    EXPECT_NE(first, 30.0);
    for (std::uint64_t k = 1; k < 100; ++k) EXPECT_EQ(air.measure(k, 0.0, {30.0, 0.0, 0.0}).tas_mps, first);
}

}  // namespace
}  // namespace gdnav::sensors
