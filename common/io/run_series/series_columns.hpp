#pragma once
// Columns of the nav_recorder time-series tables (one row every `decimation` steps) and how each row is filled.
// Every column is a double in SI units named with its unit; angles in rad, NED frame (n, e, d components).
//
//   /truth     t_s lat_rad lon_rad h_m vn_mps ve_mps vd_mps yaw_rad pitch_rad bank_rad tas_mps aoa_rad aos_rad
//              dT_K dp_Pa Hp_m T_K wind_n_mps wind_e_mps wind_d_mps north_m east_m dist_m
//   /estimate  t_s lat_rad lon_rad h_m vn_mps ve_mps vd_mps yaw_rad pitch_rad bank_rad tas_mps aoa_rad aos_rad
//              dT_K Hp_m T_K wind_n_mps wind_e_mps wind_d_mps dp_Pa gnss_denied north_m east_m
//   /error     t_s yaw_rad pitch_rad bank_rad rot_rad tas_mps aoa_rad aos_rad dT_K h_m vn_mps ve_mps vd_mps
//              north_m east_m hor_m cross_m along_m
//   /gnss      t_s lat_rad lon_rad h_m vn_mps ve_mps vd_mps      (1 Hz fix epochs only, not decimated)
// north_m / east_m of truth and estimate: offsets from the initial true position with the initial radii (as the
// horizontal error); dist_m: true ground distance flown since t_GNSS (0 before). Estimate and error columns are NaN
// at steps where an estimate topic is missing (its producer died).
#include <array>
#include <string>
#include <vector>

#include "metrics/nav_errors.hpp"
#include "msgs/messages.hpp"

namespace gdnav::io::run_series {

inline constexpr std::size_t kTruthColumns = 23;
inline constexpr std::size_t kEstimateColumns = 23;
inline constexpr std::size_t kErrorColumns = 18;
inline constexpr std::size_t kGnssColumns = 7;

std::vector<std::string> truth_columns();
std::vector<std::string> estimate_columns();
std::vector<std::string> error_columns();
std::vector<std::string> gnss_columns();

// The metrics-side views of the topics.
metrics::NavState truth_state(const msg::Truth& t);
metrics::NavState estimate_state(const msg::AirDataEstimate& a, const msg::AttitudeEstimate& q,
                                 const msg::PositionEstimate& p);

struct Origin {
    double lat_rad{0.0};
    double lon_rad{0.0};
    earth::Radii radii;
};

void fill_truth_row(double* row, double t_s, const msg::Truth& t, const Origin& o, double dist_m);
// `est` null: NaN row (t_s kept).
void fill_estimate_row(double* row, double t_s, const msg::AirDataEstimate* a, const msg::AttitudeEstimate* q,
                       const msg::PositionEstimate* p, const Origin& o, double h_true_m);
void fill_error_row(double* row, double t_s, const metrics::NavErrors* e);
void fill_gnss_row(double* row, double t_s, const msg::GnssSample& g);

}  // namespace gdnav::io::run_series
