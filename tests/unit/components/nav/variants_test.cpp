// The navigation variants (config/nav/variants/*.yaml): each is selectable by config and runs on synthetic data
// (60 s GNSS-aided then 60 s GNSS-denied in a constant-rate turn with wind), and each changes what it should.
#include <gtest/gtest.h>

#include <map>

#include "nav_chain.hpp"

using namespace gdnav;
using namespace gdnav::nav;

namespace {

struct Metrics {
    double att_mean_deg{0.0};   // mean attitude error over the steady turn, 20..60 s (GNSS-aided)
    double hor_end_m{0.0};      // horizontal position error at the end
    double h_end_m{0.0};        // altitude error at the end
    double v_end_mps{0.0};      // ground velocity error at the end
    bool finite{true};
    PositionEstimate last;
};

const std::map<std::string, Metrics>& results() {
    static const std::map<std::string, Metrics> m = [] {
        std::map<std::string, Metrics> out;
        for (const char* v : {"baseline", "att_zero_fb_derivatives", "att_zero_fn_derivatives", "hor_double_integration",
                              "hor_wind_integration", "ver_integration", "ver_airspeed_integration"}) {
            rnd::Stream s(71);
            synth::Scenario sc;
            sc.yaw_rate_rps = 0.05;
            sc.bank_rad = std::atan(0.05 * 30.0 / 9.8);
            sc.wind_n_mps = {4.0, -6.0, 0.0};
            sc.gyr_err_b_rps = 3.49e-3 * s.normal3();
            sc.acc_err_b_mps2 = 0.157 * s.normal3();
            sc.mag_err_b_nT = 530.0 * s.normal3();
            sc.b_dev_n_nT = Eigen::Vector3d(138, 89, 165).cwiseProduct(s.normal3());
            test::ChainOptions o;
            o.variant = v;
            o.steps = 12000;
            o.last_fix_step = 6000;
            const test::ChainRun r = test::run_chain(sc, o, 72);
            Metrics mt;
            int n = 0;
            for (std::size_t k = 2000; k <= 6000; ++k, ++n) mt.att_mean_deg += math::rad2deg(test::att_error(r, k));
            mt.att_mean_deg /= n;
            const std::size_t last = r.pos.size() - 1;
            mt.hor_end_m = test::hor_error_m(r, last);
            mt.h_end_m = std::abs(r.pos[last].h_m - r.data[last].truth.h_m);
            mt.v_end_mps = (r.pos[last].v_n_mps - r.data[last].truth.v_n_mps).norm();
            for (std::size_t k = 0; k <= last; ++k)
                mt.finite = mt.finite && r.pos[k].v_n_mps.allFinite() && std::isfinite(r.pos[k].h_m) &&
                            r.att[k].q_nb.coeffs().allFinite();
            mt.last = r.pos[last];
            out[v] = mt;
        }
        return out;
    }();
    return m;
}

}  // namespace

TEST(NavVariants, AllRunAndStayFinite) {
    for (const auto& [name, m] : results()) {
        EXPECT_TRUE(m.finite) << name;
        EXPECT_TRUE(m.last.gnss_denied) << name;
    }
}

TEST(NavVariants, AttitudeVariantsAreBiasedInTurnsBaselineIsNot) {
    // Paper, "Different Attitude Algorithms": dropping the whole ground-velocity derivative (in body or in NED)
    // biases the specific-force observation during turns; the baseline drops only zero-mean terms.
    // Synthetic turn: w_nb ~ 0.05 rad/s, wind 7.2 m/s, airspeed 30 m/s: missing w x wind ~ 0.36 m/s^2 (zero F_B)
    // and w x v_tas ~ 1.5 m/s^2 (zero F_N) against gravity 9.8 m/s^2.
    const auto& r = results();
    const double base = r.at("baseline").att_mean_deg;
    EXPECT_LT(base, 0.15);
    EXPECT_GT(r.at("att_zero_fb_derivatives").att_mean_deg, 3.0 * base);
    EXPECT_GT(r.at("att_zero_fn_derivatives").att_mean_deg, 3.0 * base);
    EXPECT_GT(r.at("att_zero_fn_derivatives").att_mean_deg, r.at("att_zero_fb_derivatives").att_mean_deg);
}

TEST(NavVariants, PositionVariantsChangeOnlyTheirOwnOutputs) {
    const auto& r = results();
    const Metrics& b = r.at("baseline");
    EXPECT_LT(b.hor_end_m, 10.0);
    EXPECT_LT(b.h_end_m, 3.0);
    for (const char* v : {"hor_double_integration", "hor_wind_integration"}) {
        const Metrics& m = r.at(v);
        EXPECT_EQ(m.att_mean_deg, b.att_mean_deg) << v;  // attitude untouched before the loss
        EXPECT_GT((m.last.v_n_mps - b.last.v_n_mps).norm(), 0.01) << v;
        EXPECT_LT(m.hor_end_m, 50.0) << v;
        EXPECT_EQ(m.last.h_m, b.last.h_m) << v;  // altitude still from pressure
    }
    for (const char* v : {"ver_integration", "ver_airspeed_integration"}) {
        const Metrics& m = r.at(v);
        EXPECT_GT(std::abs(m.last.h_m - b.last.h_m), 1e-3) << v;
        EXPECT_LT(m.h_end_m, 10.0) << v;
        // Horizontal velocity only through p_n feedback (altitude in gravity and transport rate): < 1 mm/s.
        EXPECT_LT((m.last.v_n_mps - b.last.v_n_mps).head<2>().norm(), 1e-3) << v;
    }
    EXPECT_EQ(r.at("ver_airspeed_integration").last.wind_n_mps.z(), 0.0);
}

TEST(NavVariants, BadVariantValuesAreRejectedWithTheAllowedChoices) {
    PositionFilter p;
    const config::Config tuning = config::Config::wrap(test::load_tuning_node(false)["position"], "tuning.yaml");
    try {
        p.configure(tuning, config::Config::parse("horizontal: frozen\nvertical: pressure\n", "v.yaml"), rnd::Stream(1));
        FAIL() << "accepted a bad variant";
    } catch (const config::ConfigError& e) {
        EXPECT_NE(std::string(e.what()).find("frozen_wind, double_integration, wind_integration"), std::string::npos)
            << e.what();
    }
    AttitudeFilter a;
    const config::Config atun = config::Config::wrap(test::load_tuning_node(false)["attitude"], "tuning.yaml");
    EXPECT_THROW(a.configure(atun, config::Config::parse("specific_force: baseline\ntypo: 1\n", "v.yaml"),
                             rnd::Stream(1)),
                 config::ConfigError);
}
