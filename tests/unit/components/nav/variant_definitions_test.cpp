// The six navigation variants against the paper's definitions. The tests feed the model
// functions the filters call (att::observe, denied::step) inputs crafted so that the term in question is the only
// one that differs. They check that each variant drops or integrates exactly the terms of the paper's equation and
// changes nothing else. The paper (Gallo & Barrientos, "Minimization of GNSS-Denied Inertial Navigation Errors for
// Fixed Wing Autonomous UAVs"; docs/navigation.md) is cited by the \label of its LaTeX source. The equation numbers
// are counted in order through the numbered rows of that source.
//
//   variant file               | model switch                   | paper
//   baseline                   | specific_force: baseline       | (17) filter_att_obs_fIBB
//                              | horizontal: frozen_wind        | (27)-(30) filter_pos_Deltap, _vWINDN, _vTASN, _vN
//                              | vertical: pressure             | (31), (32) GNC_Navigation_AirDataFilterGNSSDenied_H
//                              |                                |   and ..._h
//   att_zero_fb_derivatives    | specific_force: zero_fb_...    | (43) Ana_AttFilter_fibb_option2
//   att_zero_fn_derivatives    | specific_force: zero_fn_...    | (45) Ana_AttFilter_fibb_option3
//   hor_double_integration     | horizontal: double_integration | (33), (34) Ana_PosFilter_xhor_double_vndot, _vn
//   hor_wind_integration       | horizontal: wind_integration   | (33), (35)-(38) ..._xhor_wind_vtasN, _vwinddotN,
//                              |                                |   ..._xhor_double_vwindN, ..._xhor_double_vN
//   ver_integration            | vertical: integration          | (39) Ana_PosFilter_h_integr_h
//   ver_airspeed_integration   | vertical: airspeed_integration | (40), (41) Ana_PosFilter_h_tas_integr_vtas, _h
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "attitude_filter.hpp"
#include "attitude_model.hpp"
#include "config/config.hpp"
#include "denied_rules.hpp"
#include "math/rotation.hpp"
#include "nav_earth.hpp"
#include "position_filter.hpp"
#include "random/stream.hpp"

using namespace gdnav::nav;  // earth:: below is the filters' view, gdnav::nav::earth
namespace config = gdnav::config;
namespace math = gdnav::math;
namespace rnd = gdnav::rnd;
using Vec3 = Eigen::Vector3d;

namespace {

// |a - b| within 1e-12 relative to the size of b (observations mix m/s^2 and nT; velocities are tens of m/s).
::testing::AssertionResult near(const Vec3& a, const Vec3& b, double rel = 1e-12) {
    const double err = (a - b).norm();
    if (err <= rel * (1.0 + b.norm())) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "|a - b| = " << err << "\n a = " << a.transpose()
                                         << "\n b = " << b.transpose();
}

// ------------------------------------------------------------------ attitude: the specific-force observation
constexpr auto kBase = att::SpecificForceModel::kBaseline;
constexpr auto kZeroFb = att::SpecificForceModel::kZeroBodyDerivatives;
constexpr auto kZeroFn = att::SpecificForceModel::kZeroNedDerivatives;

const Quat kQ = math::quat_from_euler({math::deg2rad(60.0), math::deg2rad(4.0), math::deg2rad(25.0)});
const Vec3 kW{0.02, -0.01, 0.15};  // w_nb_b in a banked turn [rad/s]

// Filter state with every component non-zero (the quaternion is unit, so R(q) is a rotation).
att::StateVec state(const Vec3& w = kW) {
    att::StateVec x;
    x.segment<4>(att::kQ) = math::to_wxyz(kQ);
    x.segment<3>(att::kW) = w;
    x.segment<3>(att::kEgyr) = Vec3(1e-3, -2e-3, 5e-4);
    x.segment<3>(att::kEmag) = Vec3(300.0, -200.0, 150.0);
    x.segment<3>(att::kBdev) = Vec3(120.0, 80.0, -160.0);
    return x;
}

// p_n with every member non-zero (values of a flight at 45 deg latitude, exaggerated Earth terms).
att::PnVector full_pn() {
    att::PnVector pn;
    pn.g_model_n = {0.0, 0.0, 9.806};
    pn.b_model_n = {18000.0, -600.0, 47000.0};
    pn.v_n = {20.0, -24.0, 1.5};
    pn.wind_n = {3.0, -4.0, 0.7};
    pn.w_ie_n = {5.2e-5, 0.0, -5.2e-5};
    pn.w_en_n = {-3.8e-6, -3.1e-6, 3.8e-6};
    pn.a_cor_n = {-2.5e-3, 1.1e-3, -3.0e-3};
    pn.acc_err_b = {0.05, -0.08, 0.12};
    return pn;
}

Vec3 body(const Vec3& v_n) { return kQ.conjugate() * v_n; }  // q* (x) v^N (x) q
Vec3 acc(const att::MeasVec& y) { return y.segment<3>(att::kYacc); }
Vec3 gyr(const att::MeasVec& y) { return y.segment<3>(att::kYgyr); }
Vec3 mag(const att::MeasVec& y) { return y.segment<3>(att::kYmag); }

// The NED terms every variant keeps: q* (x) (w_en x v + a_cor - g_model) (x) q + E_acc.
Vec3 kept_terms(const att::PnVector& pn) {
    return body(pn.w_en_n.cross(pn.v_n) + pn.a_cor_n - pn.g_model_n) + pn.acc_err_b;
}

}  // namespace

TEST(NavVariantDefinitions, BaselineObservationIsEquations15To17) {
    const att::PnVector pn = full_pn();
    const att::StateVec x = state();
    const att::MeasVec y = att::observe(x, pn, kBase);
    // (15) gyro and (16) magnetometer, identical in every variant (checked below).
    EXPECT_TRUE(near(gyr(y), kW + body(pn.w_ie_n + pn.w_en_n) + x.segment<3>(att::kEgyr)));
    EXPECT_TRUE(near(mag(y), body(pn.b_model_n - x.segment<3>(att::kBdev)) + x.segment<3>(att::kEmag)));
    // (17): w_nb x [q* (x) (v - v_wind) (x) q] + q* (x) (w_en x v + a_cor - g_model) (x) q + E_acc.
    EXPECT_TRUE(near(acc(y), kW.cross(body(pn.v_n - pn.wind_n)) + kept_terms(pn)));
}

TEST(NavVariantDefinitions, ZeroFbDerivativesIsEquation43) {
    // Paper (19) keeps w_eb x (v_tas + v_turb + v_wind)^B + (v_tas + v_turb + v_wind)^B_dot. With
    // v_wind^B_dot = q* (x) v_wind^N_dot (x) q - w_nb x v_wind^B, the baseline's v_wind^N_dot = 0 leaves the term
    // -w_nb x v_wind^B, which cancels the wind in the coupling term (hence v - v_wind in (17)). "Zero F_B" sets the
    // whole v^B_dot = 0 instead (42), so the wind stays in the coupling term: (43) = (17) + w_nb x v_wind^B exactly.
    const att::PnVector pn = full_pn();
    const att::StateVec x = state();
    const att::MeasVec base = att::observe(x, pn, kBase);
    const att::MeasVec fb = att::observe(x, pn, kZeroFb);
    EXPECT_TRUE(near(acc(fb), kW.cross(body(pn.v_n)) + kept_terms(pn)));  // (43) as written
    EXPECT_TRUE(near(acc(fb) - acc(base), kW.cross(body(pn.wind_n))));
    EXPECT_EQ(gyr(fb), gyr(base));
    EXPECT_EQ(mag(fb), mag(base));

    // Only w_nb and the wind non-zero: the baseline sees -w_nb x v_wind^B, zero F_B sees nothing.
    att::PnVector only_wind;
    only_wind.wind_n = pn.wind_n;
    EXPECT_TRUE(near(acc(att::observe(x, only_wind, kBase)), -kW.cross(body(pn.wind_n))));
    EXPECT_TRUE(near(acc(att::observe(x, only_wind, kZeroFb)), Vec3::Zero()));
    // No wind, or no body rate: the two observations are the same (the variants differ only in that term).
    att::PnVector no_wind = pn;
    no_wind.wind_n.setZero();
    EXPECT_TRUE(near(acc(att::observe(x, no_wind, kZeroFb)), acc(att::observe(x, no_wind, kBase)), 1e-15));
    const att::StateVec still = state(Vec3::Zero());
    EXPECT_TRUE(near(acc(att::observe(still, pn, kZeroFb)), acc(att::observe(still, pn, kBase)), 1e-15));
}

TEST(NavVariantDefinitions, ZeroFnDerivativesIsEquation45) {
    // "Zero F_N" sets v^N_dot = 0 in the NED form (20), see (44): the observation is (20) without v^N_dot rotated into
    // body, (45) = q* (x) (w_en x v + a_cor - g_model) (x) q + E_acc. Against (17) the whole coupling term
    // w_nb x [q* (x) (v - v_wind) (x) q] goes, and only it: the transport-rate term w_en x v stays.
    const att::PnVector pn = full_pn();
    const att::StateVec x = state();
    const att::MeasVec base = att::observe(x, pn, kBase);
    const att::MeasVec fn = att::observe(x, pn, kZeroFn);
    EXPECT_TRUE(near(acc(fn), kept_terms(pn)));  // (45) as written
    EXPECT_TRUE(near(acc(base) - acc(fn), kW.cross(body(pn.v_n - pn.wind_n))));
    EXPECT_EQ(gyr(fn), gyr(base));
    EXPECT_EQ(mag(fn), mag(base));

    // Only w_nb and the ground velocity non-zero: the baseline sees w_nb x v^B, zero F_N nothing.
    att::PnVector only_v;
    only_v.v_n = pn.v_n;
    EXPECT_TRUE(near(acc(att::observe(x, only_v, kBase)), kW.cross(body(pn.v_n))));
    EXPECT_TRUE(near(acc(att::observe(x, only_v, kZeroFn)), Vec3::Zero()));
    // Only the transport rate and the ground velocity: kept by (45), w_en x v rotated into body.
    only_v.w_en_n = pn.w_en_n;
    const att::StateVec still = state(Vec3::Zero());
    EXPECT_TRUE(near(acc(att::observe(still, only_v, kZeroFn)), body(pn.w_en_n.cross(pn.v_n))));
    // The accelerometer rows no longer depend on w_nb: their Jacobian columns are zero (baseline: -[v_b x]).
    const att::MeasJac h_fn = att::observation_jacobian(x, pn, kZeroFn);
    EXPECT_TRUE((h_fn.block<3, 3>(att::kYacc, att::kW).isZero(0.0)));
    const att::MeasJac h_base = att::observation_jacobian(x, pn, kBase);
    EXPECT_LT((h_base.block<3, 3>(att::kYacc, att::kW) + math::skew(body(pn.v_n - pn.wind_n))).norm(), 1e-12);
}

// ------------------------------------------------------------------ GNSS-denied reconstruction (denied_rules)
namespace {

constexpr double kDt = 0.01;
using denied::HorizontalRule;
using denied::VerticalRule;

denied::DeniedState prev_state() {
    denied::DeniedState s;
    s.lat_rad = math::deg2rad(40.0);
    s.lon_rad = math::deg2rad(-3.0);
    s.h_m = 1200.0;
    s.v_n_mps = {20.0, -24.0, 1.5};
    s.wind_n_mps = {3.0, -4.0, 0.7};
    s.dp_Pa = 150.0;
    return s;
}

denied::DeniedInputs inputs() {
    denied::DeniedInputs in;
    in.q_nb = kQ;
    in.w_nb_b_rps = kW;
    in.f_b_mps2 = {0.4, 0.3, -9.9};
    in.air.tas_mps = 30.0;
    in.air.aoa_rad = 0.06;
    in.air.aos_rad = 0.02;
    in.air.Hp_m = 1100.0;
    in.air.dT_K = 5.0;
    in.air.tas_dot_mps2 = 0.3;
    in.air.aoa_dot_rps = 0.01;
    in.air.aos_dot_rps = -0.02;
    return in;
}

denied::DeniedState step(HorizontalRule hor, VerticalRule ver, const denied::DeniedState& prev = prev_state(),
                         const denied::DeniedInputs& in = inputs()) {
    return denied::step(prev, in, kDt, hor, ver);
}

Vec3 vtas_n(const denied::DeniedInputs& in) {  // (29): q (x) v_TAS^B(v_tas, alpha, beta) (x) q*
    return in.q_nb * math::vtas_body(in.air.tas_mps, in.air.aoa_rad, in.air.aos_rad);
}

// The Earth terms of (33) written out (wgs84.hpp): w_en = (v_E/(N+h), -v_N/(M+h), -v_E tan(lat)/(N+h)),
// a_cor = 2 w_ie x v with w_ie = w (cos lat, 0, -sin lat), g_model = (0, 0, g(lat, h)).
Vec3 v_dot_33(const denied::DeniedInputs& in, const denied::DeniedState& prev) {
    const double lat = prev.lat_rad, h = prev.h_m;
    const Vec3& v = prev.v_n_mps;
    const earth::Radii r = earth::radii(lat);
    const Vec3 w_en(v.y() / (r.n_m + h), -v.x() / (r.m_m + h), -v.y() * std::tan(lat) / (r.n_m + h));
    const Vec3 a_cor = 2.0 * Vec3(earth::kWie_rps * std::cos(lat), 0.0, -earth::kWie_rps * std::sin(lat)).cross(v);
    const Vec3 g(0.0, 0.0, earth::normal_gravity(lat, h).g_mps2);
    return in.q_nb * in.f_b_mps2 - w_en.cross(v) + g - a_cor;
}

// (31), (32): H from (Hp, dT, dp) by INSA, then h = R_E H / (R_E - H).
double h_32(const denied::DeniedInputs& in, double dp_pa) {
    const double big_h = earth::H_from_Hp(in.air.Hp_m, in.air.dT_K, dp_pa);
    return earth::kRE_m * big_h / (earth::kRE_m - big_h);
}

// Longitude and latitude integrate this step's ground velocity in every rule (radii at lat(k-1), this step's h).
void expect_position_integrates_velocity(const denied::DeniedState& prev, const denied::DeniedState& s) {
    const earth::Radii r = earth::radii(prev.lat_rad);
    EXPECT_NEAR(s.lat_rad, prev.lat_rad + kDt * s.v_n_mps.x() / (r.m_m + s.h_m), 1e-15);
    EXPECT_NEAR(s.lon_rad, prev.lon_rad + kDt * s.v_n_mps.y() / ((r.n_m + s.h_m) * std::cos(prev.lat_rad)), 1e-15);
}

// The baseline's vertical rule, kept by the horizontal variants: dp frozen (27), altitude from pressure (31), (32);
// and the position integrates this step's velocity.
void expect_vertical_is_baseline(const denied::DeniedState& prev, const denied::DeniedInputs& in,
                                 const denied::DeniedState& s) {
    EXPECT_EQ(s.dp_Pa, prev.dp_Pa);
    EXPECT_NEAR(s.h_m, h_32(in, prev.dp_Pa), 1e-9);
    expect_position_integrates_velocity(prev, s);
}

// A vertical variant changes nothing but the altitude (and, for airspeed integration, the vertical velocity and
// wind): the first n components of velocity and wind and dp are the baseline's; the position uses the new altitude.
void expect_only_altitude_changed(const denied::DeniedState& s, int n) {
    const denied::DeniedState prev = prev_state();
    const denied::DeniedState base = step(HorizontalRule::kFrozenWind, VerticalRule::kPressure);
    EXPECT_EQ(s.v_n_mps.head(n), base.v_n_mps.head(n));
    EXPECT_EQ(s.wind_n_mps.head(n), base.wind_n_mps.head(n));
    EXPECT_EQ(s.dp_Pa, base.dp_Pa);
    expect_position_integrates_velocity(prev, s);
}

}  // namespace

TEST(NavVariantDefinitions, BaselineDeniedRulesAreEquations27To32) {
    const denied::DeniedState prev = prev_state();
    const denied::DeniedInputs in = inputs();
    const denied::DeniedState s = step(HorizontalRule::kFrozenWind, VerticalRule::kPressure);
    EXPECT_EQ(s.wind_n_mps, prev.wind_n_mps);                    // (28) frozen
    EXPECT_TRUE(near(s.v_n_mps, prev.wind_n_mps + vtas_n(in)));  // (29), (30)
    expect_vertical_is_baseline(prev, in, s);                    // (27), (31), (32)
    // No integration of anything but the position: the previous velocity and altitude, the specific force, the body
    // rate and the air data rates leave velocity, wind and altitude unchanged.
    denied::DeniedState prev2 = prev;
    prev2.v_n_mps = {-5.0, 7.0, -2.0};
    prev2.h_m = 500.0;
    denied::DeniedInputs in2 = in;
    in2.f_b_mps2 = {3.0, -2.0, -5.0};
    in2.w_nb_b_rps = {0.3, 0.2, -0.1};
    in2.air.tas_dot_mps2 = -2.0;
    in2.air.aoa_dot_rps = 0.2;
    in2.air.aos_dot_rps = 0.1;
    const denied::DeniedState s2 = step(HorizontalRule::kFrozenWind, VerticalRule::kPressure, prev2, in2);
    EXPECT_EQ(s2.v_n_mps, s.v_n_mps);
    EXPECT_EQ(s2.wind_n_mps, s.wind_n_mps);
    EXPECT_EQ(s2.h_m, s.h_m);
}

TEST(NavVariantDefinitions, DoubleIntegrationIsEquations33And34) {
    const denied::DeniedState prev = prev_state();
    const denied::DeniedInputs in = inputs();
    const denied::DeniedState s = step(HorizontalRule::kDoubleIntegration, VerticalRule::kPressure);
    // (34) with (33): Earth terms at step n-1 (the previous position and velocity), f and q of this step.
    EXPECT_TRUE(near(s.v_n_mps, prev.v_n_mps + kDt * v_dot_33(in, prev)));
    // Only the specific-force term non-zero: at rest (w_en x v = a_cor = 0) with f cancelling gravity except for a
    // 0.5 m/s^2 push along NED north, the velocity grows by exactly dt * 0.5 north.
    denied::DeniedState rest = prev;
    rest.v_n_mps.setZero();
    denied::DeniedInputs push = in;
    push.f_b_mps2 = kQ.conjugate() * Vec3(0.5, 0.0, -earth::normal_gravity(rest.lat_rad, rest.h_m).g_mps2);
    const denied::DeniedState sr = step(HorizontalRule::kDoubleIntegration, VerticalRule::kPressure, rest, push);
    EXPECT_TRUE(near(sr.v_n_mps, Vec3(kDt * 0.5, 0.0, 0.0), 1e-12));
    // (28)-(30) discarded: neither the previous wind nor the airspeed reaches the velocity. The wind is only an
    // output, v - q (x) v_TAS^B (x) q* (the reference filter_pos01B; the paper defines none for this variant).
    denied::DeniedState prev2 = prev;
    prev2.wind_n_mps = {-9.0, 9.0, -1.0};
    denied::DeniedInputs in2 = in;
    in2.air.tas_mps = 45.0;
    in2.air.aoa_rad = -0.1;
    const denied::DeniedState s2 = step(HorizontalRule::kDoubleIntegration, VerticalRule::kPressure, prev2, in2);
    EXPECT_EQ(s2.v_n_mps, s.v_n_mps);
    EXPECT_TRUE(near(s.wind_n_mps, s.v_n_mps - vtas_n(in)));
    expect_vertical_is_baseline(prev, in, s);
}

TEST(NavVariantDefinitions, WindIntegrationIsEquations33And35To38) {
    const denied::DeniedState prev = prev_state();
    const denied::DeniedInputs in = inputs();
    const AirDataEstimate& a = in.air;
    // v_TAS^B_dot from the air data rates is the time derivative of v_TAS^B(v_tas, alpha, beta) (central difference).
    const Vec3 vtas_dot_b = denied::vtas_dot_body(a.tas_mps, a.aoa_rad, a.aos_rad, a.tas_dot_mps2, a.aoa_dot_rps,
                                                  a.aos_dot_rps);
    const double e = 1e-5;
    const auto vb = [&](double t) {
        return math::vtas_body(a.tas_mps + t * a.tas_dot_mps2, a.aoa_rad + t * a.aoa_dot_rps,
                               a.aos_rad + t * a.aos_dot_rps);
    };
    EXPECT_TRUE(near(vtas_dot_b, (vb(e) - vb(-e)) / (2.0 * e), 1e-8));

    const denied::DeniedState s = step(HorizontalRule::kWindIntegration, VerticalRule::kPressure);
    const Vec3 vtas_b = math::vtas_body(a.tas_mps, a.aoa_rad, a.aos_rad);
    const Vec3 vtas_dot_n = kQ * Vec3(vtas_dot_b + kW.cross(vtas_b));                   // (35)
    const Vec3 wind = prev.wind_n_mps + kDt * (v_dot_33(in, prev) - vtas_dot_n);        // (36), (37)
    EXPECT_TRUE(near(s.wind_n_mps, wind));
    EXPECT_TRUE(near(s.v_n_mps, wind + vtas_n(in)));                                    // (38)
    // Only the wind derivative is integrated: when the ground acceleration (33) equals the airspeed's (35), the
    // wind does not move. f is chosen so that (33) gives exactly v_TAS^N_dot.
    denied::DeniedInputs same = in;
    const Vec3 f_excess_n = vtas_dot_n - v_dot_33(in, prev);  // what (33) lacks, in NED
    same.f_b_mps2 = in.f_b_mps2 + kQ.conjugate() * f_excess_n;
    const denied::DeniedState ss = step(HorizontalRule::kWindIntegration, VerticalRule::kPressure, prev, same);
    EXPECT_TRUE(near(ss.wind_n_mps, prev.wind_n_mps, 1e-13));
    EXPECT_TRUE(near(ss.v_n_mps, prev.wind_n_mps + vtas_n(in), 1e-13));
    expect_vertical_is_baseline(prev, in, s);
}

TEST(NavVariantDefinitions, VerticalIntegrationIsEquation39) {
    const denied::DeniedState prev = prev_state();
    const denied::DeniedInputs in = inputs();
    const denied::DeniedState s = step(HorizontalRule::kFrozenWind, VerticalRule::kIntegration);
    // (39): h = h(n-1) - dt v_D with v^N of (30) (frozen 3-D wind, vertical component included, + airspeed).
    ASSERT_NE(prev.wind_n_mps.z(), 0.0);
    EXPECT_NEAR(s.h_m, prev.h_m - kDt * (prev.wind_n_mps.z() + vtas_n(in).z()), 1e-12);
    // The pressure altitude no longer enters.
    denied::DeniedInputs in2 = in;
    in2.air.Hp_m = 3000.0;
    in2.air.dT_K = -10.0;
    EXPECT_EQ(step(HorizontalRule::kFrozenWind, VerticalRule::kIntegration, prev, in2).h_m, s.h_m);
    expect_only_altitude_changed(s, 3);
}

TEST(NavVariantDefinitions, AirspeedIntegrationIsEquations40And41) {
    const denied::DeniedState prev = prev_state();
    const denied::DeniedInputs in = inputs();
    const denied::DeniedState s = step(HorizontalRule::kFrozenWind, VerticalRule::kAirspeedIntegration);
    // (40): zero vertical wind, v_D = [q (x) v_TAS^B (x) q*]_3; (41): h = h(n-1) - dt v_D.
    EXPECT_EQ(s.wind_n_mps.z(), 0.0);
    EXPECT_NEAR(s.v_n_mps.z(), vtas_n(in).z(), 1e-12);
    EXPECT_NEAR(s.h_m, prev.h_m - kDt * vtas_n(in).z(), 1e-12);
    // The frozen vertical wind (0.7 m/s here) is what separates it from (39).
    const denied::DeniedState integ = step(HorizontalRule::kFrozenWind, VerticalRule::kIntegration);
    EXPECT_NEAR(s.h_m - integ.h_m, kDt * prev.wind_n_mps.z(), 1e-12);
    expect_only_altitude_changed(s, 2);
}

TEST(NavVariantDefinitions, EachVariantFileSelectsItsRuleAndKeepsTheOthersAtBaseline) {
    struct Expected {
        const char* file;
        att::SpecificForceModel model;
        HorizontalRule hor;
        VerticalRule ver;
        AttitudeFormulation form{AttitudeFormulation::kAdditive};  // issue 14: the error-state filter
        double frozen_wind_average_s{0.0};                         // issue 14: the mean-wind freeze
    };
    const Expected table[] = {
        {"baseline", kBase, HorizontalRule::kFrozenWind, VerticalRule::kPressure},
        {"att_zero_fb_derivatives", kZeroFb, HorizontalRule::kFrozenWind, VerticalRule::kPressure},
        {"att_zero_fn_derivatives", kZeroFn, HorizontalRule::kFrozenWind, VerticalRule::kPressure},
        {"hor_double_integration", kBase, HorizontalRule::kDoubleIntegration, VerticalRule::kPressure},
        {"hor_wind_integration", kBase, HorizontalRule::kWindIntegration, VerticalRule::kPressure},
        {"ver_integration", kBase, HorizontalRule::kFrozenWind, VerticalRule::kIntegration},
        {"ver_airspeed_integration", kBase, HorizontalRule::kFrozenWind, VerticalRule::kAirspeedIntegration},
        {"att_error_state", kBase, HorizontalRule::kFrozenWind, VerticalRule::kPressure,
         AttitudeFormulation::kErrorState},
        {"eskf_mean_wind", kBase, HorizontalRule::kFrozenWind, VerticalRule::kPressure, AttitudeFormulation::kErrorState,
         45.0},
    };
    const std::string dir = std::string(GDNAV_SOURCE_DIR) + "/config/nav/";
    for (const Expected& e : table) {
        SCOPED_TRACE(e.file);
        const config::Config tuning = config::Config::load(dir + "tuning.yaml");
        const config::Config variant = config::Config::load(dir + "variants/" + e.file + ".yaml");
        const rnd::Stream root = rnd::Stream::derive(1, 0, "variant_definitions");
        AttitudeFilter att;
        PositionFilter pos;
        att.configure(tuning.child("attitude"), variant.child("attitude"), root.child("att"));
        pos.configure(tuning.child("position"), variant.child("position"), root.child("pos"));
        EXPECT_EQ(att.tuning().model, e.model);
        EXPECT_EQ(pos.tuning().horizontal, e.hor);
        EXPECT_EQ(pos.tuning().vertical, e.ver);
        EXPECT_EQ(att.tuning().formulation, e.form);
        EXPECT_EQ(pos.tuning().frozen_wind_average_s, e.frozen_wind_average_s);
    }
}
