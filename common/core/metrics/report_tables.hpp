#pragma once
// The paper's aggregated-NSE tables as Markdown (report/tables.md), in the paper's layout:
//   body attitude (yaw, pitch, bank errors: aggregated mean and std of the per-run mean and std; |dr|: also max) [deg]
//   final vertical position (geometric altitude) error [m]
//   final ground speed errors (N, E) [m/s]
//   final horizontal position error: distance since t_GNSS, cross-track, along-track and horizontal error [m, %]
// plus two tables the paper describes in words (air data; the trajectory metrics of vertical and speed errors) and
// the best and worst runs. One block per labelled batch, so two scenarios can sit side by side as in the paper.
// Signs as the paper: means, finals and signed maxima print with an explicit sign; stds and norms without.
#include <string>
#include <vector>

#include "metrics/aggregate.hpp"

namespace gdnav::core::metrics {

struct LabelledBatch {
    std::string label;  // e.g. "#1"
    BatchAggregate aggregate;
    std::vector<RunRecord> runs;
};

std::string paper_tables_markdown(const std::vector<LabelledBatch>& batches, const std::string& preamble);
// One line per run (run, every per-run metric) for scripts and spreadsheets (report/runs.csv).
std::string runs_csv(const std::vector<RunRecord>& runs);
// "%+.*f" or "%.*f".
std::string fixed(double v, int decimals, bool sign);

}  // namespace gdnav::core::metrics
namespace gdnav { namespace metrics = core::metrics; }  // the short name (docs/architecture.md, "Namespaces")
