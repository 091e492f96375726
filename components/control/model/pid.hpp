#pragma once
// The discrete PID and the set-point ramp filter of the reference autopilot (docs/guidance-control.md, "Control").
//
// DiscretePid, one call per control step (dt = control period), gains per step:
//   e_k   = error (target - measured)
//   I_k   = I_{k-1} + e_k                                   running sum: no dt factor, no anti-windup
//   ef_k  = (T_f ef_{k-1} + dt e_k) / (T_f + dt)            first-order low-pass of the error
//   D_k   = ef_k - ef_{k-1}                                 no division by dt
//   u_k   = u_eq + K_p e_k + K_i I_k + K_d D_k,  clamped to [u_min, u_max]
// reset() sets I = 0 and ef = 0 (so the first D after a reset is dt/(T_f + dt) e_1).
//
// RampFilter, one call per control step, N = ramp steps of the active mode (time constant ~ N dt):
//   y_k = (N y_{k-1} + u_k) / (N + 1)                       N = 0 passes the set point through
namespace gdnav::control {

struct PidGains {
    double kp{0.0};
    double ki{0.0};
    double kd{0.0};
    double u_eq{0.0};
    double u_min{0.0};
    double u_max{0.0};
};

class DiscretePid {
public:
    DiscretePid() = default;
    DiscretePid(const PidGains& gains, double filter_time_s, double dt_s);

    // Changes the gains and keeps the state (I, ef).
    void set_gains(const PidGains& gains) { gains_ = gains; }
    void reset();

    // Advances the state with error e and returns u_k before the clamp.
    double step_unsaturated(double error);
    // Advances the state and returns the clamped u_k.
    double step(double error) { return saturate(step_unsaturated(error)); }
    [[nodiscard]] double saturate(double u) const;

    [[nodiscard]] const PidGains& gains() const { return gains_; }
    [[nodiscard]] double integral() const { return integral_; }
    [[nodiscard]] double filtered_error() const { return filtered_; }
    [[nodiscard]] double derivative() const { return derivative_; }

private:
    PidGains gains_{};
    double filter_time_s_{0.0};
    double dt_s_{1.0};
    double integral_{0.0};
    double filtered_{0.0};
    double derivative_{0.0};
};

class RampFilter {
public:
    void reset(double value) { y_ = value; }
    void set_steps(double n) { n_ = n; }
    double step(double u) {
        y_ = (n_ * y_ + u) / (n_ + 1.0);
        return y_;
    }
    [[nodiscard]] double value() const { return y_; }
    [[nodiscard]] double steps() const { return n_; }

private:
    double y_{0.0};
    double n_{0.0};
};

}  // namespace gdnav::control
