// Aircraft file loader and validation, mass properties, aerodynamic tables, propulsion.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "atmosphere/insa.hpp"
#include "flight_physics/model/aircraft_model.hpp"

using namespace gdnav;
using physics::AircraftModel;

namespace {
const std::string kFile = std::string(GDNAV_SOURCE_DIR) + "/config/aircraft/mugin.yaml";

std::string mugin_text() {
    std::ifstream in(kFile);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Replaces the first occurrence of `from` (must exist) and parses the result.
std::string error_of(const std::string& from, const std::string& to) {
    std::string text = mugin_text();
    const auto pos = text.find(from);
    if (pos == std::string::npos) return "pattern not found: " + from;
    text.replace(pos, from.size(), to);
    try {
        (void)AircraftModel::from_config(config::Config::parse(text, "bad_mugin.yaml"));
    } catch (const config::ConfigError& e) {
        return e.what();
    }
    return "no error";
}

bool names(const std::string& msg, const std::string& key) { return msg.find("'" + key + "'") != std::string::npos; }
}  // namespace

TEST(Aircraft, LoadsTheMuginFile) {
    const AircraftModel a = AircraftModel::load(kFile);
    EXPECT_EQ(a.name, "mugin");
    EXPECT_DOUBLE_EQ(a.geometry.wing_area_m2, 0.87754);
    EXPECT_DOUBLE_EQ(a.geometry.chord_m, 0.35894);
    EXPECT_DOUBLE_EQ(a.geometry.span_m, 2.68);
    EXPECT_DOUBLE_EQ(a.mass.full_kg, 19.715);
    EXPECT_DOUBLE_EQ(a.mass.empty_kg, 17.835);
    EXPECT_DOUBLE_EQ(a.mass.inertia_full_kgm2(0, 2), -0.191);
    EXPECT_NEAR(a.limits.elevator_rad, math::deg2rad(8.0), 1e-15);
    EXPECT_DOUBLE_EQ(a.propulsion.max_power_W, 4180.0);
}

TEST(Aircraft, MassPropertiesVaryLinearlyWithFuel) {
    const AircraftModel a = AircraftModel::load(kFile);
    // Scenario mass 19.5 kg: r = (19.715 - 19.5) / (19.715 - 17.835) = 0.114362.
    EXPECT_NEAR(a.mass.fuel_ratio(19.5), 0.215 / 1.88, 1e-12);
    const double mid = 0.5 * (19.715 + 17.835);
    EXPECT_NEAR(a.mass.cg_m(mid).x(), 0.213, 1e-12);
    EXPECT_NEAR(a.mass.cg_m(mid).z(), -0.0055, 1e-12);
    EXPECT_NEAR(a.mass.inertia_kgm2(mid)(1, 1), 0.5 * (3.462 + 3.430), 1e-12);
    EXPECT_NEAR(a.mass.inertia_kgm2(mid)(0, 2), -0.1915, 1e-12);
    EXPECT_NEAR(a.mass.inertia_kgm2(17.835)(2, 2), 5.458, 1e-12);
}

TEST(Aircraft, AeroCoefficientsReproduceTheReferenceTable) {
    const AircraftModel a = AircraftModel::load(kFile);
    // (alpha deg, C_X0 without the -0.115, C_Z0, C_m0), reference section 4.2.
    const double rows[][4] = {{-2.5, -0.0275, -0.3587, 0.0486},
                              {0.0, -0.0226, -0.5512, -0.0145},
                              {2.5, -0.0058, -0.7414, -0.0780},
                              {5.0, 0.0228, -0.9279, -0.1416},
                              {10.0, 0.1145, -1.2840, -0.2668}};
    for (const auto& r : rows) {
        const auto c = a.aero.coefficients(math::deg2rad(r[0]), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        EXPECT_NEAR(c.cx, r[1] - 0.115, 1e-12);
        EXPECT_NEAR(c.cz, r[2], 1e-12);
        EXPECT_NEAR(c.cm, r[3], 1e-12);
        EXPECT_NEAR(c.cy, 0.0, 1e-15);
        EXPECT_NEAR(c.cl, 0.0, 1e-15);
        EXPECT_NEAR(c.cn, 0.0, 1e-15);
    }
    // Derived slopes near alpha = 0 (reference: C_Z,alpha ~ -4.39 /rad, C_m,alpha ~ -1.45 /rad).
    const double d = math::deg2rad(0.5);
    const auto cp = a.aero.coefficients(d, 0, 0, 0, 0, 0, 0, 0), cm = a.aero.coefficients(-d, 0, 0, 0, 0, 0, 0, 0);
    EXPECT_NEAR((cp.cz - cm.cz) / (2 * d), -4.39, 0.05);
    EXPECT_NEAR((cp.cm - cm.cm) / (2 * d), -1.45, 0.03);
    // Surfaces: C_m,dE = -0.032 /deg, C_l,dA = +0.00421 /deg, C_n,dR = +0.00288 /deg.
    const auto base = a.aero.coefficients(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    const auto de = a.aero.coefficients(0.0, 0.0, 0.0, 0.0, 0.0, math::deg2rad(-2.0), 0.0, 0.0);
    EXPECT_NEAR(de.cm - base.cm, 0.064, 1e-12);  // negative elevator: nose up
    const auto da = a.aero.coefficients(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, math::deg2rad(1.0), 0.0);
    EXPECT_NEAR(da.cl, 0.00421, 1e-12);
    const auto dr = a.aero.coefficients(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, math::deg2rad(1.0));
    EXPECT_NEAR(dr.cn, 0.00288, 1e-12);
    // Sideslip: C_Y = +0.082 at beta = -10 deg (alpha = 5 deg); even effect on C_X: +0.0084 at |beta| = 10 deg.
    const auto b = a.aero.coefficients(math::deg2rad(5.0), math::deg2rad(-10.0), 0, 0, 0, 0, 0, 0);
    EXPECT_NEAR(b.cy, 0.082, 0.001);
    EXPECT_NEAR(b.cx - (0.0228 - 0.115), 0.0084, 1e-4);
    // Weathercock and dihedral stability signs.
    const auto bp = a.aero.coefficients(0.0, math::deg2rad(2.0), 0, 0, 0, 0, 0, 0);
    EXPECT_GT(bp.cn, 0.0);
    EXPECT_LT(bp.cl, 0.0);
}

TEST(Aircraft, AeroTablesAreC1AtTheKnots) {
    const AircraftModel a = AircraftModel::load(kFile);
    for (double knot : {0.0, 2.5, 5.0}) {
        const double x = math::deg2rad(knot), h = 1e-7;
        const auto [v0, s0] = a.aero.cz0.eval(x);
        const double left = (v0 - a.aero.cz0(x - h)) / h;
        const double right = (a.aero.cz0(x + h) - v0) / h;
        EXPECT_NEAR(left, right, 1e-4) << knot;
        EXPECT_NEAR(s0, right, 1e-4) << knot;
    }
}

TEST(Aircraft, PropulsionMatchesTheReferenceCheckValue) {
    const AircraftModel a = AircraftModel::load(kFile);
    // Reference check (acft_test/Tapm.cpp): V = 40 m/s, throttle 0.74, p = 98500 Pa, T = 265 K, rho = 1.225
    // -> n = 102.419 rps, thrust 62.747 N, torque -4.8067 N m, m_dot = -3.0932e-4 kg/s. Our Ct/Cp tables hold only
    // the reference's 0.1-step key points, hence the percent-level tolerances on n and thrust.
    const auto o = a.propulsion.compute(0.74, 40.0, 1.225, 98500.0, 265.0);
    EXPECT_NEAR(o.power_W, 4180.0 * 0.74, 1e-9);
    EXPECT_NEAR(o.speed_rps, 102.419, 0.01 * 102.419);
    EXPECT_NEAR(o.thrust_N, 62.747, 0.02 * 62.747);
    EXPECT_NEAR(o.torque_x_Nm, -4.8067, 0.01 * 4.8067);
    EXPECT_NEAR(o.mass_rate_kgps, -3.0932e-4, 1e-8);
    // The speed solves Cp(J) rho n^3 D^5 = P.
    const double j = 40.0 / (o.speed_rps * 0.51);
    EXPECT_NEAR(a.propulsion.cp(j) * 1.225 * std::pow(o.speed_rps, 3) * std::pow(0.51, 5), o.power_W, 1e-6);
    // Altitude cap: full throttle at 2700 m ISA gives P_max delta / sqrt(theta).
    const double p = atm::pressure_Pa(2700.0), T = atm::temperature_K(2700.0, 0.0);
    EXPECT_NEAR(a.propulsion.power_W(1.0, p, T), 4180.0 * (p / 101325.0) / std::sqrt(T / 288.15), 1e-9);
    EXPECT_NEAR(a.propulsion.power_W(0.3, p, T), 4180.0 * 0.3, 1e-9);
}

TEST(Aircraft, BadFilesNameTheKey) {
    std::string m = error_of("  full_kg: 19.715\n", "");
    EXPECT_TRUE(names(m, "mass.full_kg")) << m;
    m = error_of("full_kg: 19.715", "full_kg: -19.715");
    EXPECT_TRUE(names(m, "mass.full_kg")) << m;
    m = error_of("empty_kg: 17.835", "empty_kg: 20.0");
    EXPECT_TRUE(names(m, "mass.empty_kg")) << m;
    m = error_of("  chord_m: 0.35894", "  chord_m: 0.35894\n  chrod_m: 0.3");
    EXPECT_TRUE(names(m, "geometry.chrod_m")) << m;
    m = error_of("cz0:       [-0.3587, -0.5512, -0.7414, -0.9279, -1.2840]", "cz0: [-0.3587, -0.5512]");
    EXPECT_TRUE(names(m, "aerodynamics.cz0")) << m;
    m = error_of("alpha_deg: [-2.5,    0.0,     2.5,", "alpha_deg: [-2.5,    3.0,     2.5,");
    EXPECT_TRUE(names(m, "aerodynamics.alpha_deg")) << m;
    m = error_of("0.0,   3.462, 0.0,", "0.0,   -3.462, 0.0,");
    EXPECT_TRUE(names(m, "mass.inertia_full_kgm2")) << m;
    m = error_of("propeller_diameter_m: 0.51", "propeller_diameter_m: 0");
    EXPECT_TRUE(names(m, "propulsion.propeller_diameter_m")) << m;
    m = error_of("rudder_per_deg:      [-0.00517,  0.00016,  0.00288]", "rudder_per_deg: [1, 2]");
    EXPECT_TRUE(names(m, "aerodynamics.lateral.rudder_per_deg")) << m;
    m = error_of("  elevator_deg: 8.0", "  elevator_deg: -8.0");
    EXPECT_TRUE(names(m, "control_limits.elevator_deg")) << m;
    EXPECT_THROW(AircraftModel::load("/nonexistent/aircraft.yaml"), config::ConfigError);
}

TEST(Aircraft, Table1DIsExactForParabolasAndExtrapolatesLinearly) {
    // The blend of two exact parabolas is exact: y = 3 x^2 - 2 x + 1 on uneven knots.
    auto f = [](double x) { return 3.0 * x * x - 2.0 * x + 1.0; };
    const std::vector<double> xs{-1.0, 0.0, 0.5, 2.0, 3.0};
    std::vector<double> ys;
    for (double x : xs) ys.push_back(f(x));
    const physics::Table1D t(xs, ys);
    for (double x : {-0.7, 0.0, 0.2, 1.3, 2.9}) {
        EXPECT_NEAR(t(x), f(x), 1e-12) << x;
        EXPECT_NEAR(t.eval(x).second, 6.0 * x - 2.0, 1e-12) << x;
    }
    // Outside: tangent line at the end knot.
    EXPECT_NEAR(t(4.0), f(3.0) + (6.0 * 3.0 - 2.0) * 1.0, 1e-12);
    EXPECT_NEAR(t(-2.0), f(-1.0) + (6.0 * -1.0 - 2.0) * -1.0, 1e-12);
    // Two knots: straight line.
    const physics::Table1D lin({0.0, 2.0}, {1.0, 5.0});
    EXPECT_NEAR(lin(0.5), 2.0, 1e-15);
    EXPECT_NEAR(lin(3.0), 7.0, 1e-15);
    EXPECT_THROW(physics::Table1D({0.0, 0.0}, {1.0, 2.0}), std::invalid_argument);
}
