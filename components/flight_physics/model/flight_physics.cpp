#include "flight_physics/model/flight_physics.hpp"

#include <cmath>
#include <stdexcept>

namespace gdnav::physics {

namespace {
// Euclidean part of x + dt * f, and the quaternion rotated by w_nb dt (normalised).
PhysicsState propagate(const PhysicsState& x, const Vec3& pos_rate, const Vec3& v_dot, const Vec3& w_dot, double m_dot,
                       const Vec3& w_nb, double dt) {
    PhysicsState y;
    y.lon_rad = x.lon_rad + dt * pos_rate.x();
    y.lat_rad = x.lat_rad + dt * pos_rate.y();
    y.h_m = x.h_m + dt * pos_rate.z();
    y.v_n_mps = x.v_n_mps + dt * v_dot;
    y.w_ib_b_rps = x.w_ib_b_rps + dt * w_dot;
    y.mass_kg = x.mass_kg + dt * m_dot;
    y.q_nb = (x.q_nb * math::quat_from_rotv(w_nb * dt)).normalized();
    return y;
}
}  // namespace

FlightPhysics::FlightPhysics(const AircraftModel& aircraft, const EnvironmentParams& env, rnd::Stream turb_stream)
    : dyn_(aircraft, env.earth), env_(env), wind_(env.wind), offsets_(env.offsets), turb_(env.turbulence, turb_stream) {
    if (!env.magnetic.valid()) throw std::invalid_argument("FlightPhysics: magnetic model not set");
}

void FlightPhysics::evaluate(const PhysicsState& x, double t, const Vec3& turb_b, const Controls& u, DynamicsEval& e) {
    dyn_.evaluate(x, u, wind_.wind_n_mps(t), turb_b, offsets_.at(t), warm_, e);
}

void FlightPhysics::initialize_trimmed(double lat_rad, double lon_rad, double Hp_m, double tas_mps, double bearing_rad,
                                       double mass_kg, double t0_s) {
    const TrimRequest req{.lat_rad = lat_rad, .lon_rad = lon_rad, .Hp_m = Hp_m, .tas_mps = tas_mps,
                          .bearing_rad = bearing_rad, .mass_kg = mass_kg, .wind_n_mps = wind_.wind_n_mps(t0_s),
                          .offsets = offsets_.at(t0_s)};
    trim_ = trim_level_flight(dyn_, req);

    PhysicsState x = trim_.state;
    turb_.set_conditions(tas_mps, x.h_m, kSubStep_s);
    turb_.reset_stationary();
    if (turb_.active()) {
        // Ground velocity = air velocity + wind + turbulence, so the air-relative velocity is the trim one.
        const Mat3 r_nb = x.q_nb.toRotationMatrix();
        x.v_n_mps += r_nb * turb_.velocity_b_mps();
        x.w_ib_b_rps =
            r_nb.transpose() * (earth::earth_rate_n(x.lat_rad) + earth::transport_rate_n(x.lat_rad, x.h_m, x.v_n_mps));
    }
    x_ = x;
    u_ = dyn_.clamp(trim_.controls);
    t_s_ = t0_s;
    warm_ = {};
    evaluate(x_, t_s_, turb_.velocity_b_mps(), u_, eval_);
    initialized_ = true;
    update_truth();
}

void FlightPhysics::initialize(const PhysicsState& x, const Controls& u, double t0_s) {
    x_ = x;
    u_ = dyn_.clamp(u);
    t_s_ = t0_s;
    warm_ = {};
    const Vec3 vair_b = x.q_nb.conjugate() * (x.v_n_mps - wind_.wind_n_mps(t0_s));
    turb_.set_conditions(vair_b.norm(), x.h_m, kSubStep_s);
    turb_.reset_stationary();
    evaluate(x_, t_s_, turb_.velocity_b_mps(), u_, eval_);
    initialized_ = true;
    update_truth();
}

void FlightPhysics::advance(const Controls& u_in, double dt_s) {
    if (!initialized_) throw std::logic_error("FlightPhysics::advance before initialize");
    if (!(dt_s > 0.0)) throw std::invalid_argument("FlightPhysics::advance: dt must be > 0");
    const Controls u = dyn_.clamp(u_in);
    const int n = std::max(1, static_cast<int>(std::ceil(dt_s / kSubStep_s - 1e-9)));
    const double h = dt_s / n;
    const double t_start = t_s_;
    turb_.set_conditions(eval_.air.tas_mps, x_.h_m, h);

    DynamicsEval e0;
    DynamicsEval e1;
    if (u == u_) {
        e0 = eval_;
    } else {
        evaluate(x_, t_start, turb_.velocity_b_mps(), u, e0);
    }
    for (int i = 0; i < n; ++i) {
        const double t0 = t_start + i * h;
        const double t1 = t_start + (i + 1) * h;
        if (i > 0) evaluate(x_, t0, turb_.velocity_b_mps(), u, e0);
        const PhysicsState xp = propagate(x_, e0.pos_rate, e0.v_dot_n, e0.w_dot_ib_b, e0.mass_rate_kgps, e0.w_nb_b, h);
        const Vec3 turb1 = turb_.step();
        evaluate(xp, t1, turb1, u, e1);
        PhysicsState y = propagate(x_, 0.5 * (e0.pos_rate + e1.pos_rate), 0.5 * (e0.v_dot_n + e1.v_dot_n),
                                   0.5 * (e0.w_dot_ib_b + e1.w_dot_ib_b), 0.5 * (e0.mass_rate_kgps + e1.mass_rate_kgps),
                                   0.5 * (e0.w_nb_b + e1.w_nb_b), h);
        y.lon_rad = math::wrap_pi(y.lon_rad);
        x_ = y;
    }
    t_s_ = t_start + dt_s;
    u_ = u;
    evaluate(x_, t_s_, turb_.velocity_b_mps(), u_, eval_);
    update_truth();
}

void FlightPhysics::update_truth() {
    const DynamicsEval& e = eval_;
    TruthSample& s = truth_;
    s.t_s = t_s_;
    s.lon_rad = x_.lon_rad;
    s.lat_rad = x_.lat_rad;
    s.h_m = x_.h_m;
    s.v_n_mps = x_.v_n_mps;
    s.q_nb = x_.q_nb;
    s.euler = math::euler_from_dcm(e.r_nb);
    s.w_ib_b_rps = x_.w_ib_b_rps;
    s.w_nb_b_rps = e.w_nb_b;
    s.dw_ib_b_rps2 = e.w_dot_ib_b;
    s.f_ib_b_mps2 = e.f_ib_b;
    s.tas_mps = e.air.tas_mps;
    s.aoa_rad = e.air.aoa_rad;
    s.aos_rad = e.air.aos_rad;
    s.wind_n_mps = wind_.wind_n_mps(t_s_);
    s.turb_b_mps = turb_.velocity_b_mps();
    const atm::Offsets off = offsets_.at(t_s_);
    s.dT_K = off.dT_K;
    s.dp_Pa = off.dp_Pa;
    s.Hp_m = e.atm.Hp_m;
    s.H_m = e.atm.H_m;
    s.p_Pa = e.atm.p_Pa;
    s.T_K = e.atm.T_K;
    s.rho_kgpm3 = e.atm.rho_kgpm3;
    s.g_n_mps2 = e.g_true_n;
    s.g_model_n_mps2 = e.g_model_n;
    s.b_model_n_nT = env_.magnetic.field_n_nT(x_.lat_rad, x_.lon_rad);
    s.b_n_nT = s.b_model_n_nT + env_.earth.mag_dev_n_nT;
    s.mass_kg = x_.mass_kg;
    s.controls = u_;
    s.thrust_N = e.prop.thrust_N;
    s.power_W = e.prop.power_W;
    s.prop_speed_rps = e.prop.speed_rps;
}

}  // namespace gdnav::physics
