// Navigation input checks of every filter: NaN, inf and out-of-range samples are rejected, counted and never reach
// the state; a step with every sample rejected is the pure propagation. Synthetic chain (nav_chain.hpp) and filters
// run side by side on the same inputs; every figure the assertions use is printed.
#include <gtest/gtest.h>

#include <cstdio>
#include <limits>

#include "nav_chain.hpp"

using namespace gdnav;
using namespace gdnav::nav;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// A clean chain run whose samples and estimates feed the filters under test (open loop for each filter).
const test::ChainRun& clean_run() {
    static const test::ChainRun r = [] {
        synth::Scenario sc;
        sc.yaw_rate_rps = 0.01;
        sc.bank_rad = std::atan(0.01 * 30.0 / 9.8);
        test::ChainOptions o;
        o.steps = 3000;
        return test::run_chain(sc, o, 71);
    }();
    return r;
}

// Filters under test start from the measurements (init.mode measurements: no alignment needed).
config::Config tuning_section(const char* name) {
    return config::Config::wrap(test::load_tuning_node(false), "tuning.yaml").child(name);
}
config::Config variant_section(const char* name) {
    return config::Config::load(test::source_path("config/nav/variants/baseline.yaml")).child(name);
}

template <typename V>
bool all_finite(const V& v) {
    return v.allFinite();
}

}  // namespace

// ------------------------------------------------------------------------------------------ air data filter
TEST(NavInputChecks, AirDataFilterRejectsBadSamples) {
    const test::ChainRun& r = clean_run();
    const rnd::Stream root = rnd::Stream::derive(1, 0, "t");
    AirDataFilter clean, bad;
    clean.configure(tuning_section("air"), root);
    bad.configure(tuning_section("air"), root);
    clean.initialize(0, 0.0, r.data[0].air, r.data[0].atm);
    bad.initialize(0, 0.0, r.data[0].air, r.data[0].atm);
    // Steps 100-102: both samples bad (NaN TAS + inf pressure, out-of-range AOA + NaN T, negative pressure + 1e9 TAS)
    // -> propagation only, exactly. Steps 200, 300: one sample bad -> the other one's rows only.
    for (std::size_t k = 1; k < r.data.size(); ++k) {
        AirSample a = r.data[k].air;
        AtmSample p = r.data[k].atm;
        if (k == 100) a.tas_mps = kNaN, p.p_Pa = kInf;
        if (k == 101) a.aoa_rad = 2.0, p.T_K = kNaN;
        if (k == 102) a.tas_mps = 1e9, p.p_Pa = -5.0;
        if (k == 200) a.aos_rad = -kInf;
        if (k == 300) p.T_K = 5000.0;
        const AirDataFilter::StateVec x0 = bad.state();
        const AirDataFilter::StateCov p0 = bad.covariance();
        clean.step(k, 0.01 * k, r.data[k].air, r.data[k].atm);
        const AirDataEstimate e = bad.step(k, 0.01 * k, a, p);
        ASSERT_TRUE(all_finite(bad.state()) && all_finite(bad.covariance())) << k;
        ASSERT_TRUE(std::isfinite(e.Hp_m) && std::isfinite(e.tas_mps)) << k;
        if (k >= 100 && k <= 102) {
            const AirDataFilter::StateCov phi = filters::transition_matrix<9>(AirDataFilter::state_jacobian(), 0.01, 1);
            EXPECT_LT((bad.state() - phi * x0).cwiseAbs().maxCoeff(), 1e-12) << k;
            EXPECT_LT((bad.covariance() - (phi * p0 * phi.transpose() + Eigen::Matrix<double, 9, 9>(
                                                                                bad.tuning().q_diag.asDiagonal())))
                          .cwiseAbs()
                          .maxCoeff(),
                      1e-12)
                << k;
        }
    }
    EXPECT_EQ(bad.rejections().air, 4u);
    EXPECT_EQ(bad.rejections().atm, 4u);
    // One skipped update among 3000 leaves no visible trace at the end.
    const double dhp = std::abs(bad.state()(4) - clean.state()(4)), dtas = std::abs(bad.state()(0) - clean.state()(0));
    std::printf("air data: rejected AirSample %llu, AtmSample %llu; end |dHp| %.2e m, |dTAS| %.2e m/s\n",
                static_cast<unsigned long long>(bad.rejections().air),
                static_cast<unsigned long long>(bad.rejections().atm), dhp, dtas);
    EXPECT_LT(dhp, 0.01);
    EXPECT_LT(dtas, 0.01);
    // initialize() refuses a bad sample.
    AirDataFilter f;
    f.configure(tuning_section("air"), root);
    AirSample a = r.data[0].air;
    a.tas_mps = kNaN;
    EXPECT_THROW(f.initialize(0, 0.0, a, r.data[0].atm), std::invalid_argument);
    EXPECT_FALSE(f.initialized());
}

// ------------------------------------------------------------------------------------------ attitude filter
TEST(NavInputChecks, AttitudeFilterRejectsBadSamples) {
    const test::ChainRun& r = clean_run();
    const rnd::Stream root = rnd::Stream::derive(1, 0, "t");
    AttitudeFilter clean, bad;
    for (AttitudeFilter* f : {&clean, &bad}) {
        f->configure(tuning_section("attitude"), variant_section("attitude"), root);
        f->initialize(0, 0.0, r.data[0].imu, r.data[0].mag, r.air[0], r.data[0].gnss, nullptr);
    }
    for (std::size_t k = 1; k < r.data.size(); ++k) {
        ImuSample imu = r.data[k].imu;
        MagSample mag = r.data[k].mag;
        PositionEstimate pos = r.pos[k - 1];
        if (k == 100) imu.w_b_rps.x() = kNaN, mag.b_b_nT.z() = kInf;  // both bad: propagation only
        if (k == 101) imu.f_b_mps2.y() = 1e4, mag.b_b_nT.x() = kNaN;
        if (k == 200) imu.f_b_mps2.z() = kInf;                           // IMU bad: magnetometer rows only
        if (k == 300) mag.b_b_nT.y() = 1e7;                              // magnetometer bad: IMU rows only
        if (k == 400) pos.v_n_mps.x() = kNaN;                            // p_n source bad: the last good one
        if (k == 401) pos.lat_rad = kInf;
        const att::StateVec x0 = bad.state();
        clean.step(k, 0.01 * k, r.data[k].imu, r.data[k].mag, r.pos[k - 1]);
        bad.step(k, 0.01 * k, imu, mag, pos);
        ASSERT_TRUE(all_finite(bad.state()) && all_finite(bad.covariance())) << k;
        if (k == 100 || k == 101) {
            // Propagation only: x = normalise(x + dt f(x)).
            att::StateVec x = x0 + bad.tuning().dt_s * att::derivative(x0);
            x.segment<4>(att::kQ).normalize();
            EXPECT_LT((bad.state() - x).cwiseAbs().maxCoeff(), 1e-12) << k;
            EXPECT_EQ(bad.last_nis(), 0.0);
        }
    }
    EXPECT_EQ(bad.rejections().imu, 3u);
    EXPECT_EQ(bad.rejections().mag, 3u);
    EXPECT_EQ(bad.rejections().position, 2u);
    const double dq = math::angle_between(bad.estimate_q(), clean.estimate_q());
    std::printf("attitude: rejected IMU %llu, mag %llu, p_n %llu; end attitude difference to the clean run %.2e deg\n",
                static_cast<unsigned long long>(bad.rejections().imu),
                static_cast<unsigned long long>(bad.rejections().mag),
                static_cast<unsigned long long>(bad.rejections().position), math::rad2deg(dq));
    EXPECT_LT(math::rad2deg(dq), 0.01);
    ImuSample imu = r.data[0].imu;
    imu.w_b_rps.z() = kNaN;
    AttitudeFilter f;
    f.configure(tuning_section("attitude"), variant_section("attitude"), root);
    EXPECT_THROW(f.initialize(0, 0.0, imu, r.data[0].mag, r.air[0], r.data[0].gnss, nullptr), std::invalid_argument);
}

// The same input checks in the error-state formulation (a rejected pair propagates only).
TEST(NavInputChecks, ErrorStateAttitudeFilterRejectsBadSamples) {
    const test::ChainRun& r = clean_run();
    const rnd::Stream root = rnd::Stream::derive(1, 0, "t");
    const config::Config variant =
        config::Config::parse("specific_force: baseline\nfilter: error_state\n", "error-state variant");
    AttitudeFilter clean, bad;
    for (AttitudeFilter* f : {&clean, &bad}) {
        f->configure(tuning_section("attitude"), variant, root);
        f->initialize(0, 0.0, r.data[0].imu, r.data[0].mag, r.air[0], r.data[0].gnss, nullptr);
    }
    for (std::size_t k = 1; k < r.data.size(); ++k) {
        ImuSample imu = r.data[k].imu;
        MagSample mag = r.data[k].mag;
        PositionEstimate pos = r.pos[k - 1];
        if (k == 100) imu.w_b_rps.x() = kNaN, mag.b_b_nT.z() = kInf;  // both bad: propagation only
        if (k == 200) imu.f_b_mps2.z() = kInf;                           // IMU bad: magnetometer rows only
        if (k == 300) mag.b_b_nT.y() = 1e7;                              // magnetometer bad: IMU rows only
        if (k == 400) pos.v_n_mps.x() = kNaN;                            // p_n source bad: the last good one
        const att::StateVec x0 = bad.state();
        clean.step(k, 0.01 * k, r.data[k].imu, r.data[k].mag, r.pos[k - 1]);
        bad.step(k, 0.01 * k, imu, mag, pos);
        ASSERT_TRUE(all_finite(bad.state()) && all_finite(bad.error_covariance())) << k;
        if (k == 100) {
            att::StateVec x = x0 + bad.tuning().dt_s * att::derivative(x0);
            x.segment<4>(att::kQ).normalize();
            EXPECT_LT((bad.state() - x).cwiseAbs().maxCoeff(), 1e-12) << k;
            EXPECT_EQ(bad.last_nis(), 0.0);
        }
    }
    EXPECT_EQ(bad.rejections().imu, 2u);
    EXPECT_EQ(bad.rejections().mag, 2u);
    EXPECT_EQ(bad.rejections().position, 1u);
    EXPECT_LT(math::rad2deg(math::angle_between(bad.estimate_q(), clean.estimate_q())), 0.01);
}

TEST(NavInputChecks, AttitudeFilterHoldsTheLastGoodPositionEstimate) {
    // A rejected p_n source gives exactly the step fed with the last good PositionEstimate.
    const test::ChainRun& r = clean_run();
    const rnd::Stream root = rnd::Stream::derive(1, 0, "t");
    AttitudeFilter bad, held;
    for (AttitudeFilter* f : {&bad, &held}) {
        f->configure(tuning_section("attitude"), variant_section("attitude"), root);
        f->initialize(0, 0.0, r.data[0].imu, r.data[0].mag, r.air[0], r.data[0].gnss, nullptr);
    }
    for (std::size_t k = 1; k < 600; ++k) {
        PositionEstimate pos = r.pos[k - 1];
        std::size_t good = k - 1;
        if (k >= 400 && k < 403) {
            pos.wind_n_mps.y() = kNaN;  // 400..402 bad: held = pos[398]
            good = 398;
        }
        if (k == 403) pos.acc_err_b_mps2.x() = 1e6, good = 398;
        bad.step(k, 0.01 * k, r.data[k].imu, r.data[k].mag, pos);
        held.step(k, 0.01 * k, r.data[k].imu, r.data[k].mag, r.pos[good]);
        ASSERT_EQ(bad.state(), held.state()) << k;
    }
    EXPECT_EQ(bad.rejections().position, 4u);
    EXPECT_EQ(held.rejections().total(), 0u);
}

// ------------------------------------------------------------------------------------------ position filter
TEST(NavInputChecks, PositionFilterRejectsBadSamples) {
    const test::ChainRun& r = clean_run();
    const rnd::Stream root = rnd::Stream::derive(1, 0, "t");
    // `bad` gets corrupt samples; `ref` gets the equivalent clean input (no fix instead of a corrupt fix, the last
    // good estimate instead of a corrupt one): their states must be identical.
    PositionFilter bad, ref;
    for (PositionFilter* f : {&bad, &ref}) {
        f->configure(tuning_section("position"), variant_section("position"), root);
        f->initialize(0, 0.0, r.data[0].imu, r.data[0].gnss, r.air[0], r.att[0], nullptr);
    }
    std::size_t att_good = 0, air_good = 0;
    int lost = -1, back = -1;
    for (std::size_t k = 1; k < r.data.size(); ++k) {
        GnssSample g = r.data[k].gnss, g_ref = r.data[k].gnss;
        ImuSample imu = r.data[k].imu;
        AirDataEstimate air = r.air[k];
        AttitudeEstimate att = r.att[k];
        if (k == 1300) att.q_nb.coeffs().x() = kNaN;
        if (k == 1301) att.w_nb_b_rps.z() = 1e3;
        if (k == 1400) air.tas_mps = kInf;
        if (k == 1401) air.Hp_m = kNaN;
        const bool att_ok = !(k == 1300 || k == 1301), air_ok = !(k == 1400 || k == 1401);
        if (att_ok) att_good = k;
        if (air_ok) air_good = k;
        if (k == 1550 || k == 1551) imu.f_b_mps2.x() = kNaN;  // no fix: propagation only
        if (k == 1600) imu.w_b_rps.y() = kInf;                // fix step: GNSS rows only
        // Corrupt fixes (fix steps every 100): a rejected fix is a missing fix, so the 1.5 s timeout switches to
        // denied at 20.51 s; the fix at 22 s (inf velocity) breaks the re-acquisition sequence, which restarts at
        // 23 s and ends at 27 s; 29 s: height out of range.
        if (k == 2000) g.lat_rad = kNaN, g_ref.fix_valid = false;
        if (k == 2200) g.v_n_mps.z() = kInf, g_ref.fix_valid = false;
        if (k == 2900) g.h_m = 2.0e6, g_ref.fix_valid = false;
        const aided::StateVec x0 = bad.aided_state();
        const PositionEstimate e = bad.step(k, 0.01 * k, imu, g, air, att);
        const PositionEstimate e_ref = ref.step(k, 0.01 * k, r.data[k].imu, g_ref, r.air[air_good], r.att[att_good]);
        ASSERT_TRUE(all_finite(bad.aided_state()) && all_finite(bad.aided_covariance())) << k;
        ASSERT_TRUE(bad.denied_state().allFinite()) << k;
        ASSERT_TRUE(std::isfinite(e.lat_rad) && std::isfinite(e.lon_rad) && e.v_n_mps.allFinite()) << k;
        if (k < 1550) {
            ASSERT_EQ(bad.aided_state(), ref.aided_state()) << k;
            ASSERT_EQ(bad.aided_covariance(), ref.aided_covariance()) << k;
            ASSERT_EQ(e.wind_n_mps, e_ref.wind_n_mps) << k;
        }
        if (k == 1550 || k == 1551) {
            aided::StateVec x = x0 + bad.tuning().dt_s * aided::derivative(x0, r.att[k].q_nb);
            x(aided::kLon) = math::wrap_pi(x(aided::kLon));
            EXPECT_LT((bad.aided_state() - x).cwiseAbs().maxCoeff(), 1e-12) << k;
        }
        ASSERT_EQ(e.gnss_denied, e_ref.gnss_denied) << k;
        if (e.gnss_lost_event) lost = static_cast<int>(k);
        if (e.gnss_reacquired_event) back = static_cast<int>(k);
    }
    EXPECT_EQ(lost, 2951);  // the last switch: 29 s fix rejected
    EXPECT_EQ(back, 2700);
    const auto& rj = bad.rejections();
    EXPECT_EQ(rj.gnss_invalid, 3u);
    EXPECT_EQ(rj.attitude, 2u);
    EXPECT_EQ(rj.air, 2u);
    EXPECT_EQ(rj.imu, 3u);
    EXPECT_EQ(rj.gnss_gate, 0u);
    const std::size_t last = r.data.size() - 1;
    const double dpos = (bad.denied_state() - ref.denied_state()).norm();
    std::printf("position: rejected fixes %llu, attitude %llu, air %llu, IMU %llu; end |f, E_acc| difference to the "
                "reference %.2e m/s^2\n",
                static_cast<unsigned long long>(rj.gnss_invalid), static_cast<unsigned long long>(rj.attitude),
                static_cast<unsigned long long>(rj.air), static_cast<unsigned long long>(rj.imu), dpos);
    EXPECT_LT(dpos, 1e-3);
    (void)last;
}

TEST(NavInputChecks, PositionFilterDeniedPhaseSkipsABadImuSample) {
    const test::ChainRun& r = clean_run();
    const rnd::Stream root = rnd::Stream::derive(1, 0, "t");
    PositionFilter f;
    f.configure(tuning_section("position"), variant_section("position"), root);
    f.initialize(0, 0.0, r.data[0].imu, r.data[0].gnss, r.air[0], r.att[0], nullptr);
    f.set_gnss_publisher_dead();
    for (std::size_t k = 1; k < 300; ++k) {
        ImuSample imu = r.data[k].imu;
        if (k == 200) imu.f_b_mps2.z() = kNaN;
        if (k == 201) imu.f_b_mps2.x() = -kInf;
        const filters::Vec<PositionFilter::kNd> xd0 = f.denied_state();
        const PositionEstimate e = f.step(k, 0.01 * k, imu, r.data[k].gnss, r.air[k], r.att[k]);
        ASSERT_TRUE(e.gnss_denied);
        ASSERT_TRUE(f.denied_state().allFinite() && e.v_n_mps.allFinite() && std::isfinite(e.lat_rad)) << k;
        if (k == 200 || k == 201) {
            EXPECT_EQ(f.denied_state(), xd0);  // static model, no update: unchanged
        }
    }
    EXPECT_EQ(f.rejections().imu, 2u);
}
