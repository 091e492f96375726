#pragma once
// Dryden turbulence (MIL-F-8785C, medium/high-altitude form, body axes), generated at run time from a Stream, with
// band-limited driving noise.
//
// Forming filters, V = true airspeed, T = L / V, L = L_u = L_v = L_w = 1750 ft = 533.4 m (MIL-F-8785C above
// 2000 ft; the MIL-HDBK-1797 form with L_u = 2 L_v = 2 L_w = 1750 ft is the same filter), driven by f:
//   u = sigma sqrt(2 T) G_u(s) f,  G_u(s) = 1 / (1 + T s)
//   v = sigma sqrt(T)   G_v(s) f,  G_v(s) = (1 + sqrt(3) T s) / (1 + T s)^2          (w likewise)
// With f = unit-intensity white noise (two-sided PSD 1) this is the plain Dryden model: rms sigma,
// R_u = sigma^2 e^-x, R_v = R_w = sigma^2 e^-x (1 - x/2), x = |lag| / T. Its u-component is not differentiable and at
// 500 Hz the sample-to-sample derivative has an rms of sigma sqrt(2 / (T dt)) (14 m/s^2 at sigma = 1.93 m/s).
//
// Band-limiting: f is white noise passed through a first-order low-pass F(s) = 1 / (1 + tau s)
// (`noise_time_constant_s`; tau = 0 gives the plain model). The spectrum below 1/tau is the Dryden one (unchanged
// low frequencies); above 1/tau it falls as omega^-4 instead of omega^-2, so the turbulence is differentiable. Exact
// continuous-time figures (any tau > 0):
//   rms_u^2 = sigma^2 T / (T + tau),            rms(du/dt)^2 = sigma^2 / (tau (T + tau))
//   rms_v^2 = sigma^2 T (2T + tau) / (2 (T + tau)^2),  rms(dv/dt)^2 = sigma^2 (3T + 2tau) / (2 tau (T + tau)^2)
// so d/dt(v, w) / d/dt(u) = sqrt((3T + 2 tau) / (2 (T + tau))) -> sqrt(3/2) for tau << T: one tau fits the reference's
// 0.61 / 0.75 m/s^2 (ratio 1.23).
//
// Calibration (docs/physics.md, "Turbulence"): the reference's precomputed files came from the Matlab Dryden block,
// whose band-limited noise is held over a sample time of 0.1 s by default; a hold h has the noise bandwidth of the
// low-pass with tau = h / 2, so the default tau is 0.05 s. The only number known of the files, rms(du/dt) =
// 0.61 m/s^2 at factor 1 and 500 Hz, then fixes the intensity: sigma = 0.61 sqrt(tau (T + tau)) = 0.5858 m/s at
// V = 29 m/s (intensity_for()), held constant like the files' (they were generated for one altitude and speed).
// The MIL-F-8785C chart intensity sigma(h, P) remains selectable (`probability_of_exceedance`).
//
// Discretisation at step dt (500 Hz in the physics), per axis, unit Gaussian nu_k from the model's Stream:
//   f_k+1 = b f_k + sqrt(1 - b^2) nu_k,  b = exp(-dt / tau)   (exact samples of the unit-variance OU process; b = 0
//                                                               for tau = 0: f is white)
//   x_k+1 = Phi x_k + Gamma K f_k,  y_k = c' x_k               (exact zero-order hold of the forming filter)
// u: x+ = a x + (1 - a) K_u f, a = exp(-dt / T). The gains K_u = sigma sqrt(2T / q), K_v = sigma sqrt(T / q) with
// q = dt (1 + b) / (1 - b), the zero-frequency PSD of the sampled f, match the continuous model's low-frequency
// spectrum exactly (ZOH keeps the DC gain), so the discrete model reproduces the continuous covariances to ~1e-7.
// The discretisation follows the actual airspeed and altitude (set_conditions, called once per 10-ms tick).
// Intensity sigma = factor * intensity_mps (constant, default), or factor * sigma(h, P) from the MIL-F-8785C
// high-altitude chart (JSBSim table, linear in altitude and in log10 P between the P = 1e-1, 1e-2, 1e-3 curves) when
// a probability of exceedance is given; `factor` is 0.5 in the paper.
// Output: turbulence velocity v_turb^b [m/s] (u, v, w along x_b, y_b, z_b); no gust angular rates.
#include <optional>

#include "config/config.hpp"
#include "math/rotation.hpp"
#include "random/stream.hpp"

namespace gdnav::physics {

// Calibration constants (see the header comment): the reference's rms(du/dt) at factor 1 and 500 Hz, the airspeed
// of the paper's conditions, the default noise time constant (half the Matlab block's default noise sample time)
// and the scale length L = 1750 ft.
inline constexpr double kReferenceUdotRms_mps2 = 0.61;
inline constexpr double kReferenceTas_mps = 29.0;
inline constexpr double kDefaultNoiseTimeConstant_s = 0.05;
inline constexpr double kDefaultScaleLength_m = 533.4;
// The constant intensity (factor 1) calibrated from those constants: 0.5858 m/s.
double reference_intensity_mps();

struct TurbulenceParams {
    double factor{0.5};                          // multiplies the Dryden velocities; 0 switches turbulence off
    double intensity_mps{reference_intensity_mps()};  // sigma at factor 1 when no chart is used; [0, 10]
    std::optional<double> prob_exceedance{};     // if set: sigma(h, P) from the chart instead; [1e-3, 1e-1]
    double scale_length_m{kDefaultScaleLength_m};  // L (1750 ft)
    double noise_time_constant_s{kDefaultNoiseTimeConstant_s};  // tau of the noise low-pass; 0 = plain Dryden; [0, 5]
    // Optional keys `factor`, `intensity_mps`, `probability_of_exceedance` (not both), `scale_length_m`,
    // `noise_time_constant_s` (defaults above); does not finish().
    static TurbulenceParams from_config(const config::Config& cfg);
};

// Discrete model of one axis (for tests and analysis): state z = (f, x), z+ = phi z + gamma nu, y = c' z.
template <int N>
struct TurbulenceAxisModel {
    Eigen::Matrix<double, N, N> phi;
    Eigen::Matrix<double, N, 1> gamma;
    Eigen::Matrix<double, N, 1> c;
};

class DrydenTurbulence {
public:
    using Mat2 = Eigen::Matrix2d;
    using Vec2 = Eigen::Vector2d;

    DrydenTurbulence() = default;
    // Throws std::invalid_argument on factor < 0, intensity < 0, P outside [1e-3, 1e-1], L <= 0 or tau outside
    // [0, 5] s.
    DrydenTurbulence(const TurbulenceParams& p, rnd::Stream stream);

    // MIL-F-8785C high-altitude intensity [m/s] at geometric altitude h for exceedance probability P (factor not
    // applied). Altitudes below the first chart point (500 ft) use its value.
    static double sigma_mps(double h_m, double prob_exceedance);
    // Noise time constant tau [s] for which the continuous model's rms(du/dt) equals `udot_rms_mps2` at intensity
    // sigma (factor applied) and airspeed V: the positive root of tau^2 + T tau - sigma^2 / udot_rms^2 = 0, T = L / V.
    static double noise_time_constant_for(double udot_rms_mps2, double sigma_mps, double tas_mps,
                                          double scale_length_m);
    // The inverse: intensity sigma [m/s] for which rms(du/dt) equals `udot_rms_mps2` with noise time constant tau:
    // sigma = udot_rms sqrt(tau (T + tau)), T = L / V.
    static double intensity_for(double udot_rms_mps2, double tau_s, double tas_mps, double scale_length_m);

    // Recomputes the discrete filters for airspeed V, altitude h and step dt.
    void set_conditions(double tas_mps, double h_m, double dt_s);
    // Draws the filter states (f and x, jointly) from their stationary distribution (after the first
    // set_conditions).
    void reset_stationary();
    // Advances one step dt and returns the new velocity. Three normal draws (u, v, w), no allocation.
    const math::Vec3& step();
    [[nodiscard]] const math::Vec3& velocity_b_mps() const { return out_; }
    [[nodiscard]] bool active() const { return p_.factor > 0.0; }

    // Discrete model at the current conditions: u with z = (f_u, x_u), v and w with z = (f, x_1, x_2).
    [[nodiscard]] TurbulenceAxisModel<2> u_model() const;
    [[nodiscard]] TurbulenceAxisModel<3> vw_model() const;
    [[nodiscard]] double sigma_out_mps() const { return sigma_; }  // factor * intensity, the Dryden sigma
    [[nodiscard]] const TurbulenceParams& params() const { return p_; }

private:
    TurbulenceParams p_{};
    rnd::Stream stream_{};
    double sigma_{0.0};
    double b_{0.0}, s_{1.0};      // noise low-pass: f+ = b f + s nu
    double a_u_{0.0}, g_u_{0.0};  // u filter: x+ = a x + g f
    Mat2 phi_{Mat2::Identity()};  // v, w filter: x+ = phi x + gamma f, y = c' x
    Vec2 gamma_{Vec2::Zero()};
    Vec2 c_{Vec2::Zero()};
    math::Vec3 f_{math::Vec3::Zero()};  // band-limited noise, per axis
    double x_u_{0.0};
    Vec2 x_v_{Vec2::Zero()}, x_w_{Vec2::Zero()};
    math::Vec3 out_{math::Vec3::Zero()};
};

}  // namespace gdnav::physics
