#pragma once
// The reference trajectory of an imported flight log (`gdnav import-log --reference FILE`, docs/replay.md): a CSV of
// the true position, velocity and attitude (an RTK/INS solution, or a gdnav run's own Truth), resampled onto the
// step grid and recorded as gdnav/Truth, so that a replay scores the filters against it instead of against a
// physics that flies its own trajectory. Columns (a header row, any order, no others):
//   t_s                                        time on the run's axis [s]
//   lat_rad, lon_rad  or  lat_deg, lon_deg     WGS84 geodetic latitude, longitude
//   h_m                                        height above the WGS84 ellipsoid [m]
//   v_n_mps_0..2                               ground velocity N, E, D [m/s]
//   q_nb_0..3  or  yaw_rad, pitch_rad, bank_rad  or  yaw_deg, pitch_deg, bank_deg
//                                              attitude body -> NED: quaternion (w, x, y, z) or Euler 3-2-1
//   tas_mps, aoa_rad, aos_rad, dT_K            optional, each on its own: true airspeed, angles of attack and
//                                              sideslip, temperature offset (without one, its errors are NaN)
// Degrees are converted to radians as the file is read; everything after is SI.
// Resampling: every column linearly between the two rows around t_k (longitude across the antimeridian, the
// quaternion normalised after interpolating towards the nearer sign); a row within kSnapS of t_k is taken as it is,
// so a reference on the grid is copied bit for bit. The rows must cover the whole grid (no extrapolation), times
// strictly increase, gaps at most max_gap_s. Truth fields the reference does not define are NaN.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "io/flight_log/log_import.hpp"
#include "msgs/messages.hpp"

namespace gdnav::io::flight_log {

inline constexpr const char* kReferenceFile = "reference.csv";  // what export-log writes from a recorded Truth

// The columns export-log writes (the SI, quaternion form; 17 significant digits, so the round trip is exact).
const std::vector<std::string>& reference_columns();
// One row of those columns from a Truth sample.
std::vector<double> reference_row(const msg::Truth& t);

class ReferenceTrack {
public:
    // Reads and checks `file` for the grid of `o` with `steps` steps; throws config::ConfigError (FILE:LINE: ...).
    ReferenceTrack(const std::filesystem::path& file, const ImportOptions& o, std::uint64_t steps);
    // The reference at grid step k (call with k = 0, 1, ...): position, velocity, attitude, Euler angles, air data.
    void fill(std::uint64_t k, msg::Truth& t);
    [[nodiscard]] std::size_t rows() const { return lines_.size(); }
    [[nodiscard]] const std::string& file() const { return file_; }
    [[nodiscard]] const std::string& form() const { return form_; }  // e.g. "lat/lon in deg, attitude as q_nb"

private:
    // Internal columns (SI): lat, lon, h, v N/E/D, q w/x/y/z, tas, aoa, aos, dT.
    static constexpr std::size_t kCols = 14;
    [[nodiscard]] const double* row(std::size_t r) const { return &values_[r * kCols]; }
    std::string file_;
    std::string form_;
    std::vector<double> t_;
    std::vector<double> values_;
    std::vector<std::size_t> lines_;
    ImportOptions grid_;
    std::size_t i_{0};
};

}  // namespace gdnav::io::flight_log
