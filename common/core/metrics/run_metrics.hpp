#pragma once
// Per-run ("trajectory") metrics, computed online at every navigation step (100 Hz):
//   for each error signal of nav_errors.hpp: mean, population std, smax (signed sample of largest |x|) and final
//   value over the steps with t in [t_start, t_end] (t_start = 0: the initial transient t < 0 is discarded, as the
//   reference does; docs/montecarlo.md, "nav_recorder: errors, online metrics and files"), and
//   the ground distance flown since the GNSS loss, D = integral from t_GNSS of sqrt(v_N^2 + v_E^2) dt of the TRUE
//   ground velocity (trapezoidal rule over the steps at or after t_GNSS; the reference's code starts it at
//   t = 1 s by an index mistake, same section — not repeated here).
// Final horizontal, cross- and along-track errors are also reported as a percentage of D (100 e / D), with D the
// distance flown up to t_end (the last step that had every estimate), so a final error is never divided by distance
// flown after it.
// Estimators that stop: a step counts in the window only when it has all three estimates; the time of each
// estimate's last step is kept, and the estimates are complete when each was present at the last step noted.
#include <array>
#include <cstdint>
#include <limits>
#include <string_view>

#include "metrics/nav_errors.hpp"
#include "metrics/linear_trend.hpp"
#include "metrics/running_stats.hpp"

namespace gdnav::core::metrics {

enum class Signal : std::uint8_t {
    yaw,
    pitch,
    bank,
    rot,
    tas,
    aoa,
    aos,
    dT,
    h,
    vn,
    ve,
    hor,
    cross,
    along,
};
inline constexpr std::size_t kSignalCount = 14;

struct SignalInfo {
    Signal signal;
    std::string_view key;   // metrics.yaml / HDF5 name, SI unit in the name
    std::string_view label;  // human readable
};
inline constexpr std::array<SignalInfo, kSignalCount> kSignals{{
    {Signal::yaw, "yaw_rad", "yaw error"},
    {Signal::pitch, "pitch_rad", "pitch error"},
    {Signal::bank, "bank_rad", "bank error"},
    {Signal::rot, "rot_rad", "attitude error |dr|"},
    {Signal::tas, "tas_mps", "TAS error"},
    {Signal::aoa, "aoa_rad", "AOA error"},
    {Signal::aos, "aos_rad", "AOS error"},
    {Signal::dT, "dT_K", "temperature offset error"},
    {Signal::h, "h_m", "altitude error"},
    {Signal::vn, "vn_mps", "north ground speed error"},
    {Signal::ve, "ve_mps", "east ground speed error"},
    {Signal::hor, "hor_m", "horizontal position error"},
    {Signal::cross, "cross_m", "cross-track error"},
    {Signal::along, "along_m", "along-track error"},
}};
constexpr std::size_t index(Signal s) { return static_cast<std::size_t>(s); }

// The three estimate topics the errors need (AirDataEstimate, AttitudeEstimate, PositionEstimate).
enum class Estimate : std::uint8_t { air_data, attitude, position };
inline constexpr std::size_t kEstimateCount = 3;
inline constexpr std::array<std::string_view, kEstimateCount> kEstimateKeys{"air_data", "attitude", "position"};
// The value of a signal in one step's errors.
double signal_value(const NavErrors& e, Signal s);

class RunMetrics {
public:
    RunMetrics() = default;
    // Trends: the attitude error angle (rot) from t_att_trend_s on (drift), the horizontal error from t_GNSS on.
    RunMetrics(double t_gnss_s, double t_start_s = 0.0, double t_att_trend_s = 500.0)
        : t_gnss_s_(t_gnss_s), t_start_s_(t_start_s), t_att_trend_s_(t_att_trend_s) {}

    // Ground speed for the distance since t_GNSS (call at every step, also before t_start and without estimates).
    void add_ground_speed(double t_s, double dt_s, double ground_speed_mps);
    // Which estimates the step at t has (call at every step, before add_errors; ignored before t_start - dt/2).
    void note_estimates(double t_s, double dt_s, const std::array<bool, kEstimateCount>& present);
    // Errors of the step at t (ignored before t_start - dt/2).
    void add_errors(double t_s, double dt_s, const NavErrors& e);

    [[nodiscard]] const RunningStats& stats(Signal s) const { return stats_[index(s)]; }
    [[nodiscard]] double distance_since_gnss_m() const { return distance_m_; }
    [[nodiscard]] double t_gnss_s() const { return t_gnss_s_; }
    [[nodiscard]] double t_last_s() const { return t_last_s_; }
    // Distance since t_GNSS flown up to t_last (the last step with errors).
    [[nodiscard]] double distance_at_t_last_m() const { return distance_at_last_m_; }
    // Time of the last noted step that had estimate e (NaN: none had it).
    [[nodiscard]] double last_estimate_s(Estimate e) const { return last_estimate_s_[static_cast<std::size_t>(e)]; }
    // True when estimate e was missing at the last step noted (its estimator stopped, or never started).
    [[nodiscard]] bool estimate_stopped(Estimate e) const;
    // False when an estimate stopped.
    [[nodiscard]] bool estimates_complete() const;
    [[nodiscard]] double t_att_trend_s() const { return t_att_trend_s_; }
    // Least-squares lines: attitude error angle [rad] vs t for t >= t_att_trend; horizontal error [m] vs t for
    // t >= t_GNSS.
    [[nodiscard]] const LinearTrend& att_trend() const { return att_trend_; }
    [[nodiscard]] const LinearTrend& hor_trend() const { return hor_trend_; }
    // 100 * final error / D (NaN when D == 0); D up to t_last when the estimates are incomplete.
    [[nodiscard]] double final_percent(Signal s) const;

private:
    static constexpr double kNoTime = std::numeric_limits<double>::quiet_NaN();
    std::array<RunningStats, kSignalCount> stats_{};
    LinearTrend att_trend_{}, hor_trend_{};
    double t_gnss_s_{100.0};
    double t_start_s_{0.0};
    double t_att_trend_s_{500.0};
    double distance_m_{0.0};
    double prev_speed_mps_{0.0};
    double prev_t_s_{0.0};
    bool have_prev_{false};
    double t_last_s_{0.0};
    double distance_at_last_m_{0.0};
    std::array<double, kEstimateCount> last_estimate_s_{kNoTime, kNoTime, kNoTime};
    double t_last_noted_s_{kNoTime};
};

}  // namespace gdnav::core::metrics
namespace gdnav { namespace metrics = core::metrics; }  // the short name (docs/architecture.md, "Namespaces")
