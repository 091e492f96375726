#pragma once
// Air data filter (paper "Air Data Filter"; docs/navigation.md "Air data filter").
//
// State (9):  x = [v_tas, aoa, aos, T, Hp, roc, v_tas_dot, aoa_dot, aos_dot]        (m/s, rad, rad, K, m, m/s, ...)
// Inputs:     AirSample (Pitot TAS, AOA and AOS vanes), AtmSample (static pressure p, outside air temperature T)
// Output:     AirDataEstimate: v_tas, aoa, aos, T, Hp, dT = T - (T0 + beta Hp), and the rate states.
// Model:      d(v_tas)/dt = v_tas_dot, d(aoa)/dt = aoa_dot, d(aos)/dt = aos_dot, d(Hp)/dt = roc, others 0
//             (A is nilpotent, A^2 = 0, so Phi = I + A dt is exact).
// Observation y = [v_tas, aoa, aos, T, p(Hp)],  p(Hp) = p0 (1 + beta Hp/T0)^(-g0/(R beta)),
//             dp/dHp = -g0 p / (R (T0 + beta Hp)).
// Difference with the paper: the paper's filter has 5 static states (x_dot = 0); the reference adds roc and the
// three rate states (a constant-rate model, needed by the "wind integration" position variant). We follow the
// reference (same Q, R, P0). There is no air data variant.
// Initialisation (truth-free, as the reference): x0 = raw measurements, Hp0 = Hp(p~), rates 0;
//   P0 = diag(sigma^2 + B0^2 for TAS, AOA, AOS, T;  dHp^2 with dHp = Hp(p~ + sqrt(sigma_p^2 + B0_p^2)) - Hp(p~);  0).
// Input checks (input_checks.hpp): an AirSample or AtmSample that is non-finite or out of range is rejected and
//   counted; the step then updates with the other sample's rows only (or just propagates when both are rejected).
//   initialize() throws on a rejected sample (the component waits for a good pair).
#include <cstdint>

#include "config/config.hpp"
#include "filters/ekf.hpp"
#include "input_checks.hpp"
#include "nav_types.hpp"
#include "random/stream.hpp"

namespace gdnav::nav {

class AirDataFilter {
public:
    static constexpr int kN = 9;
    static constexpr int kM = 5;
    using StateVec = filters::Vec<kN>;
    using StateCov = filters::SqMat<kN>;
    using MeasVec = filters::Vec<kM>;
    using MeasJac = filters::Mat<kM, kN>;

    struct Tuning {
        double dt_s{0.01};
        StateVec q_diag = StateVec::Zero();  // per-step process noise variances
        MeasVec r_diag = MeasVec::Zero();    // per-sample noise variances (tas, aoa, aos, T, p)
        MeasVec bias_sigma = MeasVec::Zero();  // bias offsets B0 (tas, aoa, aos, T, p) for P0
    };

    // tuning: the `air` section of config/nav/tuning.yaml (no variant section: there are no air data variants).
    // The stream is unused (the filter draws nothing) and kept for a uniform interface.
    void configure(const config::Config& tuning, rnd::Stream stream);
    void configure(const Tuning& tuning);

    AirDataEstimate initialize(std::uint64_t k, double t_s, const AirSample& air, const AtmSample& atm);
    AirDataEstimate step(std::uint64_t k, double t_s, const AirSample& air, const AtmSample& atm);

    // Samples rejected by the input checks since configure().
    struct Rejections {
        std::uint64_t air{0};  // AirSample (TAS, AOA, AOS)
        std::uint64_t atm{0};  // AtmSample (static pressure, temperature)
        [[nodiscard]] std::uint64_t total() const { return air + atm; }
    };
    [[nodiscard]] const Rejections& rejections() const { return rej_; }

    [[nodiscard]] bool initialized() const { return initialized_; }
    [[nodiscard]] const StateVec& state() const { return x_; }
    [[nodiscard]] const StateCov& covariance() const { return p_; }
    [[nodiscard]] const Tuning& tuning() const { return tun_; }

    // Model pieces (public for the Jacobian tests).
    static StateVec derivative(const StateVec& x);
    static StateCov state_jacobian();
    static MeasVec observe(const StateVec& x);
    static MeasJac observation_jacobian(const StateVec& x);

private:
    AirDataEstimate output(std::uint64_t k, double t_s) const;

    Tuning tun_;
    StateVec x_ = StateVec::Zero();
    StateCov p_ = StateCov::Zero();
    StateCov phi_ = StateCov::Identity();
    Rejections rej_;
    bool initialized_{false};
};

}  // namespace gdnav::nav
