// The nav_pos component (no DDS: inputs bound by hand, as the direct executor does) publishes the GNSS integrity
// events on ComponentStatus: a gate rejection, "GNSS lost: fix source untrusted" under a 500 m spoof, "GNSS
// re-acquired" when genuine fixes return, and the rejection counters, and its PositionEstimate gnss_denied follows.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "nav_chain.hpp"
#include "nav_components.hpp"
#include "nav_convert.hpp"
#include "framework/executor_access.hpp"
#include "framework/registry.hpp"

using namespace gdnav;
using namespace gdnav::nav;

namespace {

void shift_north(GnssSample& g, double m) {
    const nav::earth::Radii rr = nav::earth::radii(g.lat_rad);
    g.lat_rad += m / (rr.m_m + g.h_m);
}

bool contains(const std::vector<std::string>& v, const std::string& what) {
    for (const auto& s : v)
        if (s.find(what) != std::string::npos) return true;
    return false;
}

}  // namespace

TEST(NavPosComponent, PublishesGateRejectionsUntrustedAndReacquisitionOnComponentStatus) {
    synth::Scenario sc;
    sc.yaw_rate_rps = 0.01;
    sc.bank_rad = std::atan(0.01 * 30.0 / 9.8);
    test::ChainOptions o;
    o.steps = 6000;
    o.reference_init = false;
    const test::ChainRun r = test::run_chain(sc, o, 91);

    framework::ComponentRegistry reg;
    register_nav_components(reg);
    std::unique_ptr<framework::Component> c = reg.create("nav_pos", "nav_pos");
    const config::Config cfg = config::Config::parse(
        "{tuning: nav/tuning.yaml, variant: nav/variants/baseline.yaml, init_mode: measurements}", "test");
    framework::RunInfo info;
    info.steps = r.data.size();
    rnd::Stream stream = rnd::Stream::derive(1, 0, "nav_pos");
    c->configure(cfg, info, stream);

    msg::ImuSample imu_m;
    msg::GnssSample gnss_m;
    msg::AirDataEstimate air_m;
    msg::AttitudeEstimate att_m;
    for (framework::InputBase* in : c->inputs()) {
        if (in->topic() == topics::kImu) framework::ExecutorAccess::bind(*in, &imu_m);
        if (in->topic() == topics::kGnss) framework::ExecutorAccess::bind(*in, &gnss_m);
        if (in->topic() == topics::kAirData) framework::ExecutorAccess::bind(*in, &air_m);
        if (in->topic() == topics::kAttitude) framework::ExecutorAccess::bind(*in, &att_m);
    }
    ASSERT_EQ(c->outputs().size(), 1u);
    const auto* out = static_cast<const msg::PositionEstimate*>(c->outputs()[0]->data());

    // Fixes 500 m north from 20 s to 35 s, genuine again from 35 s.
    std::vector<std::string> status;
    std::vector<double> status_t;
    int first_denied = -1, back = -1;
    for (std::size_t k = 0; k < r.data.size(); ++k) {
        GnssSample g = r.data[k].gnss;
        if (k >= 2000 && k < 3500 && g.fix_valid) shift_north(g, 500.0);
        imu_m.f_b_mps2(framework::to_array(r.data[k].imu.f_b_mps2));
        imu_m.w_b_rps(framework::to_array(r.data[k].imu.w_b_rps));
        gnss_m.fix_valid(g.fix_valid);
        gnss_m.lon_rad(g.lon_rad);
        gnss_m.lat_rad(g.lat_rad);
        gnss_m.h_m(g.h_m);
        gnss_m.v_n_mps(framework::to_array(g.v_n_mps));
        to_msg(r.air[k], air_m);
        to_msg(r.att[k], att_m);
        const framework::StepContext ctx{k, r.data[k].truth.t_s, 0.01, k + 1 == r.data.size()};
        c->step(ctx);
        for (auto& m : framework::ExecutorAccess::take_status(*c)) {
            std::printf("  status t=%.2f s: %s\n", ctx.t_s, m.c_str());
            status.push_back(m);
            status_t.push_back(ctx.t_s);
        }
        const PositionEstimate e = from_msg(*out);
        if (e.gnss_denied && first_denied < 0) first_denied = static_cast<int>(k);
        if (first_denied >= 0 && !e.gnss_denied && back < 0) back = static_cast<int>(k);
    }
    EXPECT_EQ(first_denied, 2400);  // 5th rejected fix
    EXPECT_EQ(back, 3900);          // 5th genuine fix after 35 s
    EXPECT_TRUE(contains(status, "GNSS fix rejected by the chi-square gate"));
    EXPECT_TRUE(contains(status, "GNSS lost: fix source untrusted after 5 consecutive fixes"));
    EXPECT_TRUE(contains(status, "GNSS re-acquired: back to GNSS-aided after 5 consecutive consistent fixes"));
    EXPECT_TRUE(contains(status, "end of run: rejected samples"));
    EXPECT_TRUE(contains(status, "rejected by the chi-square gate 5"));
    EXPECT_TRUE(contains(status, "refused for re-acquisition 10"));  // fixes 25..34 s
}
