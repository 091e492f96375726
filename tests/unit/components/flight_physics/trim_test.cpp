// Trim against the reference's trim table (section 4.4: aero0 tables + propeller model, m = 19.5 kg, ISA).
#include "flight_physics/model/trim.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace gdnav;
using namespace gdnav::physics;

namespace {
const std::string kFile = std::string(GDNAV_SOURCE_DIR) + "/config/aircraft/mugin.yaml";

TrimRequest request(double v, double chi_deg = 0.0) {
    TrimRequest r;
    r.lat_rad = math::deg2rad(45.0);
    r.lon_rad = math::deg2rad(-90.0);
    r.Hp_m = 2700.0;
    r.tas_mps = v;
    r.bearing_rad = math::deg2rad(chi_deg);
    r.mass_kg = 19.5;
    return r;
}
}  // namespace

TEST(Trim, MatchesTheReferenceTrimTable) {
    const Dynamics dyn(AircraftModel::load(kFile), earth::EarthTruthParams{});
    struct Row {
        double v, alpha_deg, elevator_deg, throttle, thrust_N, power_W, n_rps;
    };
    const Row table[] = {{29.0, 0.07, -0.50, 0.43, 47.7, 1804.0, 89.8},
                         {24.0, 3.71, -3.42, 0.29, 38.0, 1212.0, 78.2},
                         {34.0, -2.07, 1.18, 0.64, 60.6, 2662.0, 102.6}};
    for (const Row& r : table) {
        const TrimResult t = trim_level_flight(dyn, request(r.v));
        EXPECT_LT(t.residual, 1e-9);
        EXPECT_NEAR(math::rad2deg(t.aoa_rad), r.alpha_deg, 0.3) << r.v;
        EXPECT_NEAR(t.controls.throttle, r.throttle, 0.03) << r.v;
        // Secondary quantities: the elevator (our CG correction and alpha interpolation differ slightly from the
        // reference's full tables), thrust, power and propeller speed.
        EXPECT_NEAR(math::rad2deg(t.controls.elevator_rad), r.elevator_deg, 0.3) << r.v;
        EXPECT_NEAR(t.eval.prop.thrust_N, r.thrust_N, 0.03 * r.thrust_N) << r.v;
        EXPECT_NEAR(t.eval.prop.power_W, r.power_W, 0.06 * r.power_W) << r.v;
        EXPECT_NEAR(t.eval.prop.speed_rps, r.n_rps, 0.03 * r.n_rps) << r.v;
        // Wings level, pitch = alpha, small lateral trim balancing the propeller torque.
        EXPECT_EQ(t.euler.bank_rad, 0.0);
        EXPECT_NEAR(t.euler.pitch_rad, t.aoa_rad, 1e-15);
        EXPECT_LT(std::abs(math::rad2deg(t.controls.aileron_rad)), 2.0);
        EXPECT_LT(std::abs(math::rad2deg(t.aos_rad)), 2.0);
        RecordProperty("trim_" + std::to_string(static_cast<int>(r.v)),
                       "alpha_deg=" + std::to_string(math::rad2deg(t.aoa_rad)) +
                           " throttle=" + std::to_string(t.controls.throttle) +
                           " elevator_deg=" + std::to_string(math::rad2deg(t.controls.elevator_rad)) +
                           " aileron_deg=" + std::to_string(math::rad2deg(t.controls.aileron_rad)) +
                           " rudder_deg=" + std::to_string(math::rad2deg(t.controls.rudder_rad)) +
                           " beta_deg=" + std::to_string(math::rad2deg(t.aos_rad)));
    }
}

TEST(Trim, LiftEqualsWeightAndThrustBalancesDrag) {
    // Independent balance in wind axes at beta ~ 0: L = m g cos(gamma) with gamma = 0, T cos(alpha) ~ D.
    const Dynamics dyn(AircraftModel::load(kFile), earth::EarthTruthParams{});
    const TrimResult t = trim_level_flight(dyn, request(29.0));
    const double a = t.aoa_rad;
    const Vec3 f = t.eval.force_aero_b;
    const double lift = -f.z() * std::cos(a) + f.x() * std::sin(a);
    const double g = earth::normal_gravity_mps2(math::deg2rad(45.0), t.state.h_m);
    EXPECT_NEAR(lift + t.eval.prop.thrust_N * std::sin(a), 19.5 * g, 0.01 * 19.5 * g);
}

TEST(Trim, GroundTrackFollowsTheRequestedBearingInWind) {
    const Dynamics dyn(AircraftModel::load(kFile), earth::EarthTruthParams{});
    TrimRequest r = request(29.0, -72.0);
    r.wind_n_mps = Vec3(3.39 * std::cos(math::deg2rad(-105.0)), 3.39 * std::sin(math::deg2rad(-105.0)), 0.0);
    r.offsets = {5.0, -300.0};
    const TrimResult t = trim_level_flight(dyn, r);
    const Vec3& v = t.state.v_n_mps;
    EXPECT_NEAR(std::atan2(v.y(), v.x()), math::deg2rad(-72.0), 1e-12);
    EXPECT_NEAR(v.z(), 0.0, 1e-12);
    EXPECT_NEAR((v - r.wind_n_mps).norm(), 29.0, 1e-9);
    // Pressure altitude at the trim point is the requested one.
    EXPECT_NEAR(t.eval.atm.Hp_m, 2700.0, 1e-6);
}

TEST(Trim, InfeasibleTrimThrows) {
    const Dynamics dyn(AircraftModel::load(kFile), earth::EarthTruthParams{});
    EXPECT_THROW(trim_level_flight(dyn, request(12.0)), std::runtime_error);
}
