// Air data filter on synthetic air data: low-pass behaviour, INSA temperature offset, rate of climb.
#include <gtest/gtest.h>

#include "nav_chain.hpp"

using namespace gdnav;
using namespace gdnav::nav;

namespace {
AirDataFilter make_filter() {
    const config::Config tuning = config::Config::wrap(test::load_tuning_node(true)["air"], "tuning.yaml");
    AirDataFilter f;
    f.configure(tuning, rnd::Stream(1));
    return f;
}
}  // namespace

TEST(NavAir, LowPassesNoisyAirDataAndEstimatesTemperatureOffset) {
    synth::Scenario sc;  // level flight: tas 30 m/s, aoa 0.03 rad, dT 5 K, dp 300 Pa
    synth::Generator gen(sc, rnd::Stream(61));
    AirDataFilter f = make_filter();
    synth::Sample s = gen.next();
    f.initialize(0, 0.0, s.air, s.atm);
    double sum_e = 0.0, sum_e2 = 0.0, sum_raw2 = 0.0;
    int n = 0;
    AirDataEstimate e;
    for (int k = 1; k <= 12000; ++k) {
        s = gen.next();
        e = f.step(static_cast<std::uint64_t>(k), s.truth.t_s, s.air, s.atm);
        if (k > 6000) {
            const double err = e.tas_mps - sc.tas_mps;
            sum_e += err;
            sum_e2 += err * err;
            sum_raw2 += std::pow(s.air.tas_mps - sc.tas_mps, 2);
            ++n;
        }
    }
    // Raw TAS noise is 0.333 m/s; the filter output noise must be several times smaller and unbiased.
    EXPECT_NEAR(std::sqrt(sum_raw2 / n), 0.333, 0.02);
    EXPECT_LT(std::sqrt(sum_e2 / n), 0.1);
    EXPECT_NEAR(sum_e / n, 0.0, 0.05);
    EXPECT_NEAR(e.aoa_rad, sc.aoa_rad, math::deg2rad(0.1));
    // dT = T - (T0 + beta Hp) from the filtered T and Hp: the synthetic atmosphere has dT = 5 K.
    EXPECT_NEAR(e.dT_K, sc.dT_K, 0.05);
    EXPECT_NEAR(e.Hp_m, s.truth.Hp_m, 2.0);
    EXPECT_NEAR(e.T_K, nav::earth::kT0_K + sc.dT_K + nav::earth::kBetaT_Kpm * s.truth.Hp_m, 0.02);
}

TEST(NavAir, EstimatesRateOfClimb) {
    synth::Scenario sc;
    sc.pitch_rad = 0.08;  // flight path angle = pitch - aoa = 0.05 rad: climb ~1.5 m/s
    synth::Generator gen(sc, rnd::Stream(62));
    AirDataFilter f = make_filter();
    synth::Sample s = gen.next();
    f.initialize(0, 0.0, s.air, s.atm);
    const double hp_start = s.truth.Hp_m;
    AirDataEstimate e;
    const int steps = 12000;
    double roc_sum = 0.0, tas_dot_sum = 0.0;
    for (int k = 1; k <= steps; ++k) {
        s = gen.next();
        e = f.step(static_cast<std::uint64_t>(k), s.truth.t_s, s.air, s.atm);
        if (k > steps / 2) {
            roc_sum += e.roc_mps;
            tas_dot_sum += e.tas_dot_mps2;
        }
    }
    const double roc_true = (s.truth.Hp_m - hp_start) / (steps * sc.dt_s);  // steady climb: constant dHp/dt
    EXPECT_GT(roc_true, 1.0);
    // The barometer noise (100 Pa ~ 8.5 m per sample) makes the instantaneous rate noisy (the reference tuning
    // lets roc walk by 0.03 m/s per step); its 60 s mean must be unbiased.
    EXPECT_NEAR(roc_sum / (steps / 2), roc_true, 0.1);
    EXPECT_NEAR(tas_dot_sum / (steps / 2), 0.0, 0.02);
    EXPECT_NEAR(e.Hp_m, s.truth.Hp_m, 3.0);
}
