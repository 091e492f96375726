#pragma once
// Aggregated metrics over the runs of a batch (paper §"Navigation System Error"; docs/montecarlo.md, "Aggregation and
// report").
// Each per-run metric (the mean, std, smax and final value of every error signal, the distance since t_GNSS and the
// final errors in % of it) is aggregated across runs into
//   mean  = (1/R) sum v_r,   std = sqrt((1/R) sum (v_r - mean)^2)   (population std, as the paper),
//   max   = the v_r of largest |v_r|, sign kept.
// For the per-run "max" metric the mean and std are those of |smax_r| and the max is the signed smax of the signed
// values (as the reference's aggregation code). Non-finite values (e.g. a percentage with zero distance) are
// skipped; n counts the rest.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "metrics/run_record.hpp"

namespace gdnav::core::metrics {

struct Aggregate {
    double mean{0.0};
    double std{0.0};
    double max{0.0};
    std::size_t n{0};
};

Aggregate aggregate(const std::vector<double>& values);
Aggregate aggregate_abs_max(const std::vector<double>& values);

struct SignalAggregate {
    Aggregate mean;   // of the per-run means
    Aggregate std;    // of the per-run stds
    Aggregate max;    // of the per-run smax (|.| convention above)
    Aggregate final;  // of the per-run final values
};

struct BatchAggregate {
    std::size_t runs{0};
    std::vector<std::uint64_t> run_indices;
    std::array<SignalAggregate, kSignalCount> signals{};
    Aggregate distance;
    Aggregate hor_pct;
    Aggregate cross_pct;
    Aggregate along_pct;
    [[nodiscard]] const SignalAggregate& operator[](Signal s) const { return signals[index(s)]; }
};

BatchAggregate aggregate_runs(const std::vector<RunRecord>& runs);
// report/aggregate.yaml: every aggregate with 17 significant digits.
std::string to_yaml(const BatchAggregate& a);

}  // namespace gdnav::core::metrics
namespace gdnav { namespace metrics = core::metrics; }  // the short name (docs/architecture.md, "Namespaces")
