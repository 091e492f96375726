#pragma once
// GNSS loss logic, a pure function of simulated time (no wall clock):
//   the navigation enters GNSS-denied mode at the first step with  t_s - t_last_valid_fix > timeout (1.5 s),
//   or at the first step after set_publisher_dead() (the runtime declared the GNSS publisher dead),
//   or when the position filter declares the fix source untrusted (force_denied(): too many consecutive fixes
//   failed its chi-square gate), whichever comes first. update() reports the timeout / publisher-dead switch once
//   (the component publishes it as a MODE status). While denied, update() ignores fixes: the way back is the
//   position filter's re-acquisition (position_filter.hpp), which calls reacquire() (the reference has none).
// Comparison tolerance: elapsed > timeout + 1e-6 s, so that t_s = t0 + k dt rounding never switches one step early.
namespace gdnav::nav {

class GnssLossMonitor {
public:
    explicit GnssLossMonitor(double timeout_s = 1.5) : timeout_s_(timeout_s) {}

    void reset(double t_last_fix_s) {
        t_last_fix_s_ = t_last_fix_s;
        denied_ = false;
        publisher_dead_ = false;
    }
    void set_publisher_dead() { publisher_dead_ = true; }
    // The runtime restarted the GNSS publisher: its fixes count again (re-acquisition brings the filter back).
    void set_publisher_alive() { publisher_dead_ = false; }
    // The fix source is untrusted: denied from now on (no event from update()).
    void force_denied() { denied_ = true; }
    // Back to GNSS-aided at a valid fix of time t_s (not while the publisher is declared dead).
    void reacquire(double t_s) {
        t_last_fix_s_ = t_s;
        denied_ = false;
    }

    // Call once per step with the step's time and whether a valid fix arrived. Returns true on the switching step.
    bool update(double t_s, bool fix_valid) {
        if (denied_) return false;
        if (fix_valid && !publisher_dead_) {
            t_last_fix_s_ = t_s;
            return false;
        }
        if (publisher_dead_ || t_s - t_last_fix_s_ > timeout_s_ + kTolerance_s) {
            denied_ = true;
            return true;
        }
        return false;
    }

    [[nodiscard]] bool denied() const { return denied_; }
    [[nodiscard]] bool publisher_dead() const { return publisher_dead_; }
    [[nodiscard]] double last_fix_s() const { return t_last_fix_s_; }
    [[nodiscard]] double timeout_s() const { return timeout_s_; }

private:
    static constexpr double kTolerance_s = 1e-6;
    double timeout_s_;
    double t_last_fix_s_{0.0};
    bool denied_{false};
    bool publisher_dead_{false};
};

}  // namespace gdnav::nav
