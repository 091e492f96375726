#pragma once
// `gdnav import-log`: a flight log in the CSV layout (log_layout.hpp) resampled onto the lockstep grid
// t_k = t0 + k dt and written as a recording (<run_dir>/record/run.mcap + digest.yaml, replacing one there), ready for
// `gdnav run --replay <run_dir>`. Resampling rule (docs/replay.md):
//   * imu, mag, air, atm (continuous signals): linear interpolation between the two samples around t_k; a sample
//     within kSnapS of t_k is taken as it is. The grid must lie inside every file's time span (no extrapolation)
//     and consecutive samples may be at most max_gap_s apart.
//   * gnss (fixes): a fix is published at the grid step nearest its time (fix_valid true); every other step
//     repeats the last fix's values with fix_valid false (zeros before the first fix), as gdnav's receiver does.
//     Two fixes on one step are an error. Gaps are allowed (signal loss).
//   * alignment.csv (optional): its values go into the align_* fields of every ImuSample / MagSample. Without it
//     they are zero and the filters need `init_mode: measurements`.
//   * reference (optional, --reference FILE): the true trajectory, resampled and recorded as gdnav/Truth
//     (log_reference.hpp); without it a replay has no reference and writes no error metrics.
#include <cstdint>
#include <filesystem>
#include <optional>

namespace gdnav::io::flight_log {

inline constexpr double kSnapS = 1e-6;         // a sample this close to a grid instant is taken as it is
inline constexpr double kDefaultMaxGapS = 0.5;  // largest allowed gap of a continuous signal

struct ImportOptions {
    std::filesystem::path csv_dir;
    std::filesystem::path run_dir;
    double t0_s{0.0};
    double dt_s{0.01};
    std::optional<std::uint64_t> steps;  // default: as many as every continuous file covers
    double max_gap_s{kDefaultMaxGapS};
    std::optional<std::filesystem::path> reference;  // CSV of the true trajectory (log_reference.hpp)
};

// Throws config::ConfigError (one line: file, line, column) on bad input.
void import_log(const ImportOptions& o);

}  // namespace gdnav::io::flight_log
