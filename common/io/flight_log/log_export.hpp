#pragma once
// `gdnav export-log`: a recorded gdnav run (<run_dir>/record/*.cdr) written in the CSV layout of log_layout.hpp,
// each sensor group at its own rate (a divisor of the grid rate; GNSS: only steps with a valid fix), plus
// alignment.csv from the first ImuSample and MagSample, and reference.csv (every step) when Truth was recorded.
// docs/replay.md.
#include <filesystem>
#include <map>
#include <string>

namespace gdnav::io::flight_log {

struct ExportOptions {
    std::filesystem::path run_dir;
    std::filesystem::path csv_dir;
    std::map<std::string, double> rates_hz;  // group name (imu, mag, air, atm, gnss) -> rate; absent = every step
};

// Throws config::ConfigError on bad options or unreadable records.
void export_log(const ExportOptions& o);

}  // namespace gdnav::io::flight_log
