#pragma once
// gdnav::physics::FlightPhysics — the true flight of the aircraft in its environment (plain C++, no DDS, no clock).
//
// Equations: see dynamics.hpp (rigid body over WGS84, aero + thrust + true gravity + Coriolis/transport).
// Environment: wind ramp (wind_ramp.hpp), INSA offsets ramp (atmosphere/offsets_ramp.hpp), Dryden turbulence in
// body axes (dryden.hpp, its own Stream), true gravity and magnetic field (earth/gravity.hpp, earth/magnetic.hpp).
// Integration: Heun (improved Euler) at 500 Hz, i.e. 5 sub-steps per 10-ms tick, controls held over the tick:
//   predictor  x* = x_k + dt f(x_k, t_k),       q* = q_k (x) Exp(w_nb(x_k) dt)
//   corrector  x_k+1 = x_k + dt/2 [f(x_k, t_k) + f(x*, t_k + dt)],  q_k+1 = q_k (x) Exp(dt/2 [w_nb(x_k) + w_nb(x*)])
// (quaternion normalised; longitude wrapped to (-pi, pi]). Time-varying inputs (wind, offsets, turbulence) are
// evaluated at t_k and t_k + dt; the turbulence advances one sample per sub-step and its filters follow the
// airspeed and altitude at the start of each tick.
//
// Use: construct; initialize_trimmed(...) (or initialize(...) with any state); then once per tick
// advance(u) and read truth(). The truth sample at t refers to the state at t and the controls of the last advance
// (for the initial sample: the trim controls).
#include "earth/magnetic.hpp"
#include "flight_physics/model/dryden.hpp"
#include "flight_physics/model/trim.hpp"
#include "flight_physics/model/truth_sample.hpp"
#include "flight_physics/model/wind_ramp.hpp"

namespace gdnav::physics {

// Everything a scenario generator draws for one run (plus the magnetic model, which must be valid()).
struct EnvironmentParams {
    WindRampParams wind{};             // default: no wind
    atm::OffsetsRampParams offsets{};  // default: ISA
    TurbulenceParams turbulence{};     // default: factor 0.5, calibrated constant intensity (dryden.hpp)
    earth::EarthTruthParams earth{};   // default: true = model fields
    earth::MagneticModel magnetic{};   // e.g. MagneticModel::load("config/earth/magnetic_wisconsin.yaml")
};

class FlightPhysics {
public:
    static constexpr double kSubStep_s = 0.002;  // 500 Hz

    // Throws std::invalid_argument when the magnetic model is not set or the turbulence parameters are invalid.
    FlightPhysics(const AircraftModel& aircraft, const EnvironmentParams& env, rnd::Stream turbulence_stream);

    // Trimmed steady straight level flight at (lat, lon), pressure altitude Hp, true airspeed V, ground-track
    // bearing chi and mass m at time t0 (the offsets and wind at t0 are used). The turbulence starts stationary;
    // the initial ground velocity includes it, so the initial TAS, AOA and AOS are the trim values.
    void initialize_trimmed(double lat_rad, double lon_rad, double Hp_m, double tas_mps, double bearing_rad,
                            double mass_kg, double t0_s);
    // Any initial state (controls held until the first advance).
    void initialize(const PhysicsState& x, const Controls& u, double t0_s);

    // Integrates over [t, t + dt] with u held constant (clamped to the limits); dt is split into sub-steps of
    // at most 2 ms.
    void advance(const Controls& u, double dt_s = 0.01);

    [[nodiscard]] const TruthSample& truth() const { return truth_; }
    [[nodiscard]] const PhysicsState& state() const { return x_; }
    [[nodiscard]] double time_s() const { return t_s_; }
    [[nodiscard]] const TrimResult& trim() const { return trim_; }  // of initialize_trimmed
    [[nodiscard]] const Dynamics& dynamics() const { return dyn_; }

private:
    void evaluate(const PhysicsState& x, double t, const Vec3& turb_b, const Controls& u, DynamicsEval& e);
    void update_truth();

    Dynamics dyn_;
    EnvironmentParams env_;
    WindRamp wind_;
    atm::OffsetsRamp offsets_;
    DrydenTurbulence turb_;
    PhysicsState x_{};
    Controls u_{};
    double t_s_{0.0};
    bool initialized_{false};
    DynamicsWarmStart warm_{};
    DynamicsEval eval_{};  // evaluation at (x_, t_s_, u_): the truth and the next first stage
    TrimResult trim_{};
    TruthSample truth_{};
};

}  // namespace gdnav::physics
