#pragma once
// The CSV layout of flight logs (docs/replay.md): one file per sensor group, a header row, a time column `t_s` and
// the SI fields of the group's IDL message (idl/gdnav.idl), arrays as NAME_0, NAME_1, NAME_2:
//   imu.csv   t_s, f_b_mps2_0..2, w_b_rps_0..2                 -> gdnav/ImuSample
//   mag.csv   t_s, b_b_nT_0..2                                 -> gdnav/MagSample
//   air.csv   t_s, tas_mps, aoa_rad, aos_rad                   -> gdnav/AirSample
//   atm.csv   t_s, p_Pa, T_K                                   -> gdnav/AtmSample
//   gnss.csv  t_s, lon_rad, lat_rad, h_m, v_n_mps_0..2         -> gdnav/GnssSample (one row per valid fix)
//   alignment.csv (optional, one row): the align_* fields of ImuSample and MagSample (pre-flight alignment)
// Shared by `gdnav import-log` and `gdnav export-log`.
#include <string>
#include <vector>

namespace gdnav::io::flight_log {

// One CSV column: its name and the double it maps to in a sample of the group's message type.
struct LogField {
    std::string name;
    double& (*ref)(void* sample);
};

struct LogGroup {
    std::string name;               // imu, mag, air, atm, gnss (file name.csv, key of --rates)
    std::string topic;              // gdnav/ImuSample, ...
    std::vector<LogField> fields;   // the columns after t_s
    bool fixes{false};              // gnss: rows are fixes placed at the nearest step; else continuous signals
    double& (*t_s)(void* sample);   // the sample's stamp time
    bool& (*fix_valid)(void* sample){nullptr};  // gnss only
};

const std::vector<LogGroup>& log_groups();

// alignment.csv: the columns for ImuSample (imu) and MagSample (mag).
struct AlignmentLayout {
    std::vector<LogField> imu;
    std::vector<LogField> mag;
};
const AlignmentLayout& alignment_layout();

inline constexpr const char* kAlignmentFile = "alignment.csv";
inline constexpr const char* kTimeColumn = "t_s";

}  // namespace gdnav::io::flight_log
