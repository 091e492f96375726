#pragma once
// The per-run metrics record, `<out_dir>/metrics.yaml` (written by nav_recorder, read by the batch runner and the
// report). Doubles are printed with 17 significant digits, so the file round-trips bit for bit and two runs are
// bit-identical in their metrics iff their files are equal byte for byte.
//
//   complete: true                 # false while running / after an interrupted or killed run
//   estimates_complete: false      # ONLY when an estimator stopped before the end (killed, lost): every figure is
//                                  # over [0, t_end], "final" is at t_end, % of the distance flown up to t_end
//   seed: 1
//   run_index: 7
//   steps: 385001                  # steps processed by the recorder
//   t_gnss_s: 100                  # GNSS loss time used for the distance
//   t_end_s: 3800                  # time of the last step in the metrics window
//   samples: 380001                # steps in the metrics window t in [0, t_end]
//   distance_since_gnss_m: ...     # true ground distance flown since t_GNSS
//   distance_at_t_end_m: ...       # ONLY with estimates_complete: false: the distance flown up to t_end
//   final_percent: {hor: ..., cross: ..., along: ...}    # 100 * final error / distance (up to t_end)
//   last_estimate_s: {air_data: ..., attitude: ..., position: ...}   # ONLY with estimates_complete: false
//   signals:                       # per error signal (run_metrics.hpp): SI units, key names carry the unit
//     yaw_rad: {mean: ..., std: ..., max: ..., final: ...}
//     ...
//
// A run without a reference trajectory (a replay whose physics is not driven by recorded Truth) has no error
// metrics: its record is `complete`, `reference: none`, seed, run_index, steps and t_gnss_s only.
#include <array>
#include <cstdint>
#include <filesystem>
#include <string>

#include "metrics/run_metrics.hpp"

namespace gdnav::core::metrics {

struct SignalSummary {
    double mean{0.0};
    double std{0.0};
    double max{0.0};  // signed smax
    double final{0.0};
};

struct RunRecord {
    bool complete{false};
    std::uint64_t seed{0};
    std::uint64_t run_index{0};
    std::uint64_t steps{0};
    double t_gnss_s{0.0};
    double t_end_s{0.0};
    std::uint64_t samples{0};
    double distance_m{0.0};
    double hor_pct{0.0};
    double cross_pct{0.0};
    double along_pct{0.0};
    // Trends (NaN when absent, e.g. in records written before they existed): slope of the attitude error angle
    // after t_att_trend_s [rad/s], slope [m/s] and r2 of the horizontal error after t_GNSS.
    double att_trend_from_s{0.0};
    double att_slope_rad_per_s{0.0};
    double hor_slope_mps{0.0};
    double hor_r2{0.0};
    std::array<SignalSummary, kSignalCount> signals{};
    // An estimator stopped before the end: the finals are at t_end and the percentages of distance_t_end_m.
    bool estimates_complete{true};
    double distance_t_end_m{0.0};  // read only when the estimates are incomplete
    std::array<double, kEstimateCount> last_estimate_s{};  // NaN: never; only meaningful when incomplete
    // false: `reference: none`, no error metrics (every figure above is NaN, samples 0).
    bool has_reference{true};
    [[nodiscard]] const SignalSummary& operator[](Signal s) const { return signals[index(s)]; }
    // The distance the final percentages divide by: flown up to t_end (the whole flight when the estimates are complete).
    [[nodiscard]] double final_distance_m() const { return estimates_complete ? distance_m : distance_t_end_m; }
};

RunRecord make_run_record(const RunMetrics& m, bool complete, std::uint64_t seed, std::uint64_t run_index,
                          std::uint64_t steps);
// The record of a run without a reference trajectory (no error metrics).
RunRecord make_unreferenced_record(bool complete, std::uint64_t seed, std::uint64_t run_index, std::uint64_t steps,
                                   double t_gnss_s);
std::string to_yaml(const RunRecord& r);
// Writes whole or not at all (files::write_whole), so a reader never sees half a file; files::WriteError otherwise.
void write_run_record(const std::filesystem::path& file, const RunRecord& r);
// Throws config::ConfigError naming the file and key when the file is missing or malformed, and for a record with
// `reference: none` (it has no error metrics to read).
RunRecord read_run_record(const std::filesystem::path& file);
// True when the file exists, parses and says complete: true.
bool run_record_complete(const std::filesystem::path& file);

// "%.17g", with .nan / .inf / -.inf for the non-finite values (YAML spelling).
std::string format_double17(double v);

}  // namespace gdnav::core::metrics
namespace gdnav { namespace metrics = core::metrics; }  // the short name (docs/architecture.md, "Namespaces")
