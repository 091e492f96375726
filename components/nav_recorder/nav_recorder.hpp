#pragma once
// nav_recorder: Truth + AirDataEstimate + AttitudeEstimate + PositionEstimate (+ GnssSample) of step k -> files.
//
// Every step (100 Hz) it computes the navigation errors (common/core/metrics/nav_errors.hpp) and updates the per-run
// metrics online (common/core/metrics/run_metrics.hpp: mean, population std, signed max and final value of each error
// over t in [0, t_end]; true ground distance since t_GNSS). Every `decimation` steps it records one row of truth,
// estimate and error. Files in RunInfo::out_dir (nothing is written when it is empty):
//
//   run.h5        HDF5 (libhdf5 1.10, no gdnav code needed to read it; layout in docs/montecarlo.md):
//                   /truth /estimate /error /gnss   tables of named double columns (series_columns.hpp)
//                   /metrics                        {name, n, mean, std, max, final} per error signal (at the end)
//                   root attributes: format = "gdnav-nav-record", format_version, complete (0 until a normal end),
//                   seed, run_index, dt_s, t0_s, decimation, t_gnss_s, steps_planned, steps_recorded,
//                   lat0_rad, lon0_rad, distance_since_gnss_m
//   metrics.yaml  the per-run record (common/core/metrics/run_record.hpp); `complete: true` only after a normal end
//
// A step enters the metrics only when it has all three estimates. An estimator that stops (killed, lost) before the
// end leaves metrics.yaml with `estimates_complete: false`, the time of each estimate's last step, and every figure
// over [0, t_end] with the final percentages of the distance flown up to t_end (run_metrics.hpp).
//
// Rows are buffered and written every `flush_rows` rows (HDF5 flush + metrics.yaml with complete: false), so a
// killed run leaves a readable file holding everything up to the last flush, marked complete = 0.
//
// Config section:
//   type: nav_recorder
//   t_gnss_s: 100        # GNSS loss time: start of the distance flown (the scenario generator writes it)
//   decimation: 10       # steps per recorded row (10 -> 10 Hz at dt 0.01 s)
//   flush_rows: 600      # rows per flush (also the HDF5 chunk size)
//   compression: 4       # deflate level 0..9 (0 = none)
//   gnss_track: true     # record the GNSS fixes (needs a GnssSample producer)
//   metrics_start_s: 0   # start of the metrics window
//   attitude_trend_from_s: 500   # start of the attitude-drift fit (metrics.yaml trends; docs/montecarlo.md)
//   reference: truth     # none: Truth is no reference (a replay without recorded Truth, set by --replay): no
//                        # errors, no metrics, truth columns NaN; metrics.yaml says `reference: none` (docs/replay.md)
#include "framework/registry.hpp"

namespace gdnav::nav_recorder {
void register_nav_recorder(framework::ComponentRegistry& reg);
}
