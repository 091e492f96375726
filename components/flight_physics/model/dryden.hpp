#pragma once
// Dryden turbulence (MIL-F-8785C, medium/high-altitude form, body axes), generated at run time from a Stream.
//
// Forming filters driven by white noise, V = true airspeed, L = L_u = L_v = L_w = 1750 ft = 533.4 m
// (MIL-F-8785C above 2000 ft; the MIL-HDBK-1797 form with L_u = 2 L_v = 2 L_w = 1750 ft is the same filter):
//   H_u(s) = sigma sqrt(2 L / (pi V)) / (1 + (L/V) s)
//   H_v(s) = H_w(s) = sigma sqrt(L / (pi V)) (1 + sqrt(3) (L/V) s) / (1 + (L/V) s)^2
// Analytic autocorrelations (tau = time lag, x = V tau / L):
//   R_u = sigma^2 e^-x,   R_v = R_w = sigma^2 e^-x (1 - x / 2).
// Discretisation at step dt (500 Hz in the physics): exact zero-order hold of the 1-state (u) and 2-state (v, w)
// state-space filters, with the input gain set so that the stationary output standard deviation equals sigma
// (discrete Lyapunov equation). For u this is x_k+1 = a x_k + sigma sqrt(1 - a^2) nu_k, a = exp(-V dt / L).
// The discretisation follows the actual airspeed and altitude (set_conditions, called once per 10-ms tick).
// Intensity sigma = sigma(h, P) from the MIL-F-8785C high-altitude chart (JSBSim table, linear in altitude and in
// log10 P between the P = 1e-1, 1e-2, 1e-3 curves); the output is multiplied by `factor` (0.5 in the paper).
// Output: turbulence velocity v_turb^b [m/s] (u, v, w along x_b, y_b, z_b); no gust angular rates.
#include "config/config.hpp"
#include "math/rotation.hpp"
#include "random/stream.hpp"

namespace gdnav::physics {

struct TurbulenceParams {
    double factor{0.5};            // multiplies the Dryden velocities; 0 switches turbulence off
    double prob_exceedance{1e-2};  // 1e-2 "light", 1e-3 "moderate"; allowed [1e-3, 1e-1]
    double scale_length_m{533.4};  // L (1750 ft)
    // Optional keys `factor`, `probability_of_exceedance`, `scale_length_m` (defaults above); does not finish().
    static TurbulenceParams from_config(const config::Config& cfg);
};

class DrydenTurbulence {
public:
    using Mat2 = Eigen::Matrix2d;
    using Vec2 = Eigen::Vector2d;

    DrydenTurbulence() = default;
    // Throws std::invalid_argument on factor < 0, P outside [1e-3, 1e-1] or L <= 0.
    DrydenTurbulence(const TurbulenceParams& p, rnd::Stream stream);

    // MIL-F-8785C high-altitude intensity [m/s] at geometric altitude h for exceedance probability P (factor not
    // applied). Altitudes below the first chart point (500 ft) use its value.
    static double sigma_mps(double h_m, double prob_exceedance);

    // Recomputes the discrete filters for airspeed V, altitude h and step dt.
    void set_conditions(double tas_mps, double h_m, double dt_s);
    // Draws the filter states from their stationary distribution (call after the first set_conditions).
    void reset_stationary();
    // Advances one step dt and returns the new velocity.
    const math::Vec3& step();
    [[nodiscard]] const math::Vec3& velocity_b_mps() const { return out_; }
    [[nodiscard]] bool active() const { return p_.factor > 0.0; }

    // Discrete model (for tests): u: x+ = a x + g nu; v, w: x+ = phi x + gamma nu, y = c x.
    [[nodiscard]] double u_pole() const { return a_u_; }
    [[nodiscard]] double u_gain() const { return g_u_; }
    [[nodiscard]] const Mat2& vw_phi() const { return phi_; }
    [[nodiscard]] const Vec2& vw_gamma() const { return gamma_; }
    [[nodiscard]] const Vec2& vw_c() const { return c_; }
    [[nodiscard]] const Mat2& vw_stationary_cov() const { return p_vw_; }  // of the state, scaled input
    [[nodiscard]] double sigma_out_mps() const { return sigma_; }          // factor * sigma(h, P)

private:
    TurbulenceParams p_{};
    rnd::Stream stream_{};
    double sigma_{0.0};
    double a_u_{0.0}, g_u_{0.0};
    Mat2 phi_{Mat2::Identity()};
    Vec2 gamma_{Vec2::Zero()};
    Vec2 c_{Vec2::Zero()};
    Mat2 p_vw_{Mat2::Zero()};
    double x_u_{0.0};
    Vec2 x_v_{Vec2::Zero()}, x_w_{Vec2::Zero()};
    math::Vec3 out_{math::Vec3::Zero()};
};

}  // namespace gdnav::physics
