// GNSS integrity of the position filter: the chi-square gate on fixes (a 500 m jump), the untrusted-source switch
// under spoofing and the re-acquisition after a GNSS outage that ends. Synthetic chain (nav_chain.hpp); every figure
// the assertions use is printed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "nav_chain.hpp"

using namespace gdnav;
using namespace gdnav::nav;

namespace {

synth::Scenario turning_scenario() {
    synth::Scenario sc;
    sc.yaw_rate_rps = 0.01;
    sc.bank_rad = std::atan(0.01 * 30.0 / 9.8);
    return sc;
}

config::Config baseline_position_variant() {
    return config::Config::load(test::source_path("config/nav/variants/baseline.yaml")).child("position");
}

// Shifts a fix north by `m` metres.
void shift_north(GnssSample& g, double m) {
    const nav::earth::Radii rr = nav::earth::radii(g.lat_rad);
    g.lat_rad += m / (rr.m_m + g.h_m);
}

}  // namespace

TEST(NavGnssIntegrity, GateRejectsASingle500mJump) {
    const synth::Scenario sc = turning_scenario();
    test::ChainOptions o;
    o.steps = 20000;
    o.edit = [](int k, synth::Sample& s) {
        if (k == 15000) shift_north(s.gnss, 500.0);  // t = 150 s
    };
    PositionFilter::Rejections rj;
    double d2 = 0.0, d2_max = 0.0;
    o.inspect = [&](int k, const PositionFilter& pf) {
        if (k == 15000) d2 = pf.gate_d2_last();
        rj = pf.rejections();
        d2_max = pf.gate_d2_max_accepted();
    };
    const test::ChainRun r = test::run_chain(sc, o, 81);
    double worst = 0.0;
    for (std::size_t k = 14000; k < r.pos.size(); ++k) {
        worst = std::max(worst, test::hor_error_m(r, k));
        ASSERT_FALSE(r.pos[k].gnss_denied) << k;
    }
    std::printf("500 m jump: d2 = %.0f (gate %.0f), rejected %llu; largest accepted d2 %.1f; worst horizontal error "
                "after it %.2f m\n",
                d2, 40.0, static_cast<unsigned long long>(rj.gnss_gate), d2_max, worst);
    EXPECT_GT(d2, 1e4);
    EXPECT_EQ(rj.gnss_gate, 1u);  // only the jump: no false alarm on 200 clean fixes
    EXPECT_LT(worst, 10.0);       // the fix never reached the state (GNSS level: sigma 2.12 m)
}

TEST(NavGnssIntegrity, PersistentSpoofingIsRejectedThenUntrustedThenRecovered) {
    // Fixes 500 m north from t = 150 s to t = 210 s (spoofing), genuine again afterwards.
    const synth::Scenario sc = turning_scenario();
    test::ChainOptions o;
    o.steps = 30000;
    o.edit = [](int k, synth::Sample& s) {
        if (k >= 15000 && k < 21000 && s.gnss.fix_valid) shift_north(s.gnss, 500.0);
    };
    PositionFilter::Rejections rj;
    std::uint64_t reacq = 0;
    o.inspect = [&](int, const PositionFilter& pf) {
        rj = pf.rejections();
        reacq = pf.reacquisitions();
    };
    const test::ChainRun r = test::run_chain(sc, o, 82);
    int lost_step = -1, back_step = -1;
    double worst = 0.0;
    for (std::size_t k = 15000; k < r.pos.size(); ++k) {
        if (r.pos[k].gnss_lost_event) lost_step = static_cast<int>(k);
        if (r.pos[k].gnss_reacquired_event) back_step = static_cast<int>(k);
        worst = std::max(worst, test::hor_error_m(r, k));
    }
    const std::size_t last = r.pos.size() - 1;
    std::printf("spoofing 150-210 s: untrusted at %.2f s after %llu gate rejections; %llu spoofed fixes refused for "
                "re-acquisition; back to aided at %.2f s; worst horizontal error %.2f m, final %.2f m\n",
                lost_step * 0.01, static_cast<unsigned long long>(rj.gnss_gate),
                static_cast<unsigned long long>(rj.gnss_reacquire), back_step * 0.01, worst,
                test::hor_error_m(r, last));
    EXPECT_EQ(lost_step, 15400);                 // 5th rejected fix (t = 154 s)
    EXPECT_EQ(rj.gnss_gate, 5u);
    EXPECT_EQ(rj.gnss_reacquire, 55u);           // fixes 155..209 s: 500 m from dead reckoning > 100 + 3 t m
    EXPECT_EQ(back_step, 21400);                 // 5th genuine fix (210..214 s)
    EXPECT_EQ(reacq, 1u);
    EXPECT_TRUE(r.pos[15400].gnss_denied);
    EXPECT_FALSE(r.pos[21400].gnss_denied);
    EXPECT_LT(worst, 30.0);                      // never pulled towards the spoofed position
    EXPECT_LT(test::hor_error_m(r, last), 5.0);
}

TEST(NavGnssIntegrity, OutageThatEndsReacquiresToGnssLevel) {
    // Fixes missing from 100 s to 300 s. A 1.5 m/s airspeed bias during the outage makes the dead-reckoning error
    // grow to ~300 m (the paper's scenarios reach 30-1000 m), so the return has something to correct.
    const synth::Scenario sc = turning_scenario();
    test::ChainOptions o;
    o.steps = 40000;
    o.edit = [](int k, synth::Sample& s) {
        if (k > 10000 && k < 30000) {
            s.gnss.fix_valid = false;
            s.air.tas_mps += 1.5;
        }
    };
    const test::ChainRun r = test::run_chain(sc, o, 83);
    int lost = -1, back = -1;
    for (std::size_t k = 0; k < r.pos.size(); ++k) {
        if (r.pos[k].gnss_lost_event) lost = static_cast<int>(k);
        if (r.pos[k].gnss_reacquired_event) back = static_cast<int>(k);
    }
    // GNSS level: the largest horizontal error over the 100 s before the outage.
    double level = 0.0;
    for (std::size_t k = 0; k < 10000; ++k) level = std::max(level, test::hor_error_m(r, k));
    const double err_at_return = test::hor_error_m(r, 30000);
    int within = -1;  // first step from which the error stays within the GNSS level (+1 m)
    for (std::size_t k = r.pos.size() - 1; k >= 30000; --k) {
        if (test::hor_error_m(r, k) > level + 1.0) break;
        within = static_cast<int>(k);
    }
    double after = 0.0;
    for (std::size_t k = 30500; k < r.pos.size(); ++k) after = std::max(after, test::hor_error_m(r, k));
    std::printf("outage 100-300 s: denied at %.2f s, error at the return %.1f m; re-acquired at %.2f s; error back "
                "within the GNSS level %.2f m (+1 m) from %.2f s (%.2f s after the first fix); max error after 305 s "
                "%.2f m\n",
                lost * 0.01, err_at_return, back * 0.01, level, within * 0.01, (within - 30000) * 0.01, after);
    EXPECT_EQ(lost, 10151);
    EXPECT_GT(err_at_return, 100.0);
    // First fix at 300 s, 5 consistent fixes -> reset on the fix of 304 s.
    EXPECT_EQ(back, 30400);
    EXPECT_FALSE(r.pos[30400].gnss_denied);
    EXPECT_TRUE(r.pos[30399].gnss_denied);
    EXPECT_GE(within, 30400);
    EXPECT_LE(within, 30500);  // back to GNSS level within 5 s of the first fix (4 s: five fixes at 1 Hz)
    EXPECT_LT(after, level + 1.0);
    // The wind low pass restarts: wind back within 0.3 m/s of the truth 10 s later.
    EXPECT_LT((r.pos[31400].wind_n_mps - sc.wind_n_mps).norm(), 0.3);
}

TEST(NavGnssIntegrity, ReacquireFixesZeroKeepsTheReferenceOneWaySwitch) {
    const synth::Scenario sc = turning_scenario();
    test::ChainOptions o;
    o.steps = 20000;
    o.position_override = YAML::Load("{gnss_integrity: {reacquire_fixes: 0}}");
    o.edit = [](int k, synth::Sample& s) {
        if (k > 5000 && k < 10000) s.gnss.fix_valid = false;
    };
    const test::ChainRun r = test::run_chain(sc, o, 84);
    for (std::size_t k = 5151; k < r.pos.size(); ++k) ASSERT_TRUE(r.pos[k].gnss_denied) << k;
}

TEST(NavGnssIntegrity, InconsistentFixesDoNotReacquire) {
    // After an outage, fixes that jump +-20 m north every second are mutually inconsistent: no re-acquisition.
    const synth::Scenario sc = turning_scenario();
    test::ChainOptions o;
    o.steps = 19999;
    o.edit = [](int k, synth::Sample& s) {
        if (k > 5000 && k < 10000) s.gnss.fix_valid = false;
        if (k >= 10000 && s.gnss.fix_valid) shift_north(s.gnss, (k / 100) % 2 == 0 ? 20.0 : -20.0);
    };
    PositionFilter::Rejections rj;
    o.inspect = [&](int, const PositionFilter& pf) { rj = pf.rejections(); };
    const test::ChainRun r = test::run_chain(sc, o, 85);
    for (std::size_t k = 5151; k < r.pos.size(); ++k) ASSERT_TRUE(r.pos[k].gnss_denied) << k;
    std::printf("alternating +-20 m fixes: %llu refused for re-acquisition\n",
                static_cast<unsigned long long>(rj.gnss_reacquire));
    EXPECT_EQ(rj.gnss_reacquire, 99u);  // fixes 101..199 s (the first of them starts a sequence)
}

TEST(NavGnssIntegrity, ConfigRejectsOutOfRangeKeys) {
    YAML::Node t = test::load_tuning_node(true);
    t["position"]["gnss_integrity"]["gate_chi2_6dof"] = 0.5;
    const rnd::Stream root = rnd::Stream::derive(1, 0, "t");
    PositionFilter f;
    EXPECT_THROW(f.configure(config::Config::wrap(t, "tuning.yaml").child("position"), baseline_position_variant(), root),
                 config::ConfigError);
    YAML::Node u = test::load_tuning_node(true);
    u["position"]["gnss_integrity"]["reacquire_after_s"] = 3.0;  // unknown key
    EXPECT_THROW(f.configure(config::Config::wrap(u, "tuning.yaml").child("position"), baseline_position_variant(), root),
                 config::ConfigError);
}
