#include "flight_physics/model/trim.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gdnav::physics {

namespace {
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
constexpr double kTolResidual = 1e-9;
constexpr int kMaxIter = 50;

Controls controls_of(const Vec6& z) { return {z(2), z(3), z(4), z(5)}; }

// Trim state for unknowns z: level relative to the air (pitch = alpha, bank = 0), heading such that the ground
// track is the requested bearing, w_nb = 0.
PhysicsState build_state(const TrimRequest& r, double h_m, const Vec6& z, math::Euler& euler) {
    const Vec3 vtas_b = math::vtas_body(r.tas_mps, z(0), z(1));
    const Vec3 va0 = math::dcm_from_euler({0.0, z(0), 0.0}) * vtas_b;  // air velocity in NED at zero heading
    const double offset = std::atan2(va0.y(), va0.x());
    const double vh = std::hypot(va0.x(), va0.y());
    const double chi = r.bearing_rad;
    const Vec3& w = r.wind_n_mps;
    const double w_perp = -w.x() * std::sin(chi) + w.y() * std::cos(chi);
    if (std::abs(w_perp) >= vh) throw std::runtime_error("trim: cross wind exceeds the airspeed");
    const double psi_air = chi - std::asin(w_perp / vh);
    const double along = vh * std::cos(psi_air - chi) + w.x() * std::cos(chi) + w.y() * std::sin(chi);
    if (!(along > 0.0)) throw std::runtime_error("trim: head wind exceeds the airspeed");
    euler = {math::wrap_pi(psi_air - offset), z(0), 0.0};

    PhysicsState x;
    x.lat_rad = r.lat_rad;
    x.lon_rad = r.lon_rad;
    x.h_m = h_m;
    x.q_nb = math::quat_from_euler(euler);
    const Mat3 r_nb = x.q_nb.toRotationMatrix();
    x.v_n_mps = r_nb * vtas_b + w;
    x.w_ib_b_rps =
        r_nb.transpose() * (earth::earth_rate_n(x.lat_rad) + earth::transport_rate_n(x.lat_rad, x.h_m, x.v_n_mps));
    x.mass_kg = r.mass_kg;
    return x;
}

Vec6 residual(const Dynamics& dyn, const TrimRequest& r, double h_m, const Vec6& z, DynamicsEval& e, PhysicsState& x,
              math::Euler& euler) {
    x = build_state(r, h_m, z, euler);
    DynamicsWarmStart warm;  // cold: the residual is a pure function of z
    dyn.evaluate(x, controls_of(z), r.wind_n_mps, Vec3::Zero(), r.offsets, warm, e);
    Vec6 res;
    res.head<3>() = e.r_nb.transpose() * e.v_dot_n;
    res.tail<3>() = e.w_dot_ib_b;
    return res;
}
}  // namespace

TrimResult trim_level_flight(const Dynamics& dyn, const TrimRequest& r) {
    if (!(r.tas_mps > 1.0) || !(r.mass_kg > 0.0)) throw std::invalid_argument("trim: airspeed and mass must be > 0");
    const double H = atm::geopotential_altitude_m(r.Hp_m, r.offsets.dT_K, r.offsets.dp_Pa);
    const double h_m = earth::geometric_from_geopotential(H);

    Vec6 z;
    z << 0.02, 0.0, 0.4, 0.0, 0.0, 0.0;
    TrimResult out;
    DynamicsEval e;
    PhysicsState x;
    math::Euler euler;
    Vec6 res = residual(dyn, r, h_m, z, e, x, euler);
    int it = 0;
    for (; it < kMaxIter && res.cwiseAbs().maxCoeff() > kTolResidual; ++it) {
        Mat6 jac;
        for (int k = 0; k < 6; ++k) {
            const double step = 1e-6;
            Vec6 zp = z, zm = z;
            zp(k) += step;
            zm(k) -= step;
            DynamicsEval ep, em;
            PhysicsState xp, xm;
            math::Euler eu;
            jac.col(k) = (residual(dyn, r, h_m, zp, ep, xp, eu) - residual(dyn, r, h_m, zm, em, xm, eu)) / (2.0 * step);
        }
        Vec6 dz = jac.fullPivLu().solve(-res);
        // Damping: keep angle updates below 5 deg and throttle updates below 0.2 per iteration.
        const double scale =
            std::min({1.0, 0.087 / std::max(std::abs(dz(0)), 1e-300), 0.087 / std::max(std::abs(dz(1)), 1e-300),
                      0.2 / std::max(std::abs(dz(2)), 1e-300)});
        z += scale * dz;
        res = residual(dyn, r, h_m, z, e, x, euler);
    }
    out.residual = res.cwiseAbs().maxCoeff();
    out.iterations = it;
    if (!(out.residual <= kTolResidual))
        throw std::runtime_error("trim: no convergence (residual " + std::to_string(out.residual) + ")");
    out.aoa_rad = z(0);
    out.aos_rad = z(1);
    out.euler = euler;
    out.controls = controls_of(z);
    out.state = x;
    out.eval = e;
    const Controls clamped = dyn.clamp(out.controls);
    if (!(clamped == out.controls))
        throw std::runtime_error("trim: outside the control limits (throttle " + std::to_string(z(2)) + ", elevator " +
                                 std::to_string(math::rad2deg(z(3))) + " deg)");
    return out;
}

}  // namespace gdnav::physics
