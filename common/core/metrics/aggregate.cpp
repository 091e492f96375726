#include "metrics/aggregate.hpp"

#include <cmath>
#include <sstream>

namespace gdnav::core::metrics {

Aggregate aggregate(const std::vector<double>& values) {
    RunningStats s;
    for (double v : values)
        if (std::isfinite(v)) s.add(v);
    Aggregate a;
    a.n = static_cast<std::size_t>(s.count());
    a.mean = s.mean();
    a.std = s.std();
    a.max = s.smax();
    return a;
}

Aggregate aggregate_abs_max(const std::vector<double>& values) {
    std::vector<double> abs_values;
    abs_values.reserve(values.size());
    for (double v : values) abs_values.push_back(std::fabs(v));
    Aggregate a = aggregate(abs_values);
    a.max = aggregate(values).max;
    return a;
}

BatchAggregate aggregate_runs(const std::vector<RunRecord>& runs) {
    BatchAggregate b;
    b.runs = runs.size();
    for (const auto& r : runs) b.run_indices.push_back(r.run_index);
    auto column = [&](auto get) {
        std::vector<double> v;
        v.reserve(runs.size());
        for (const auto& r : runs) v.push_back(get(r));
        return v;
    };
    for (const auto& info : kSignals) {
        const std::size_t i = index(info.signal);
        SignalAggregate& s = b.signals[i];
        s.mean = aggregate(column([i](const RunRecord& r) { return r.signals[i].mean; }));
        s.std = aggregate(column([i](const RunRecord& r) { return r.signals[i].std; }));
        s.max = aggregate_abs_max(column([i](const RunRecord& r) { return r.signals[i].max; }));
        s.final = aggregate(column([i](const RunRecord& r) { return r.signals[i].final; }));
    }
    // The distance each run's final percentages divide by (up to t_end; the whole flight when estimates complete).
    b.distance = aggregate(column([](const RunRecord& r) { return r.final_distance_m(); }));
    b.hor_pct = aggregate(column([](const RunRecord& r) { return r.hor_pct; }));
    b.cross_pct = aggregate(column([](const RunRecord& r) { return r.cross_pct; }));
    b.along_pct = aggregate(column([](const RunRecord& r) { return r.along_pct; }));
    return b;
}

std::string to_yaml(const BatchAggregate& b) {
    std::ostringstream o;
    auto agg = [](const Aggregate& a) {
        return "{mean: " + format_double17(a.mean) + ", std: " + format_double17(a.std) +
               ", max: " + format_double17(a.max) + ", n: " + std::to_string(a.n) + "}";
    };
    o << "# gdnav batch aggregate: across-run mean, population std and signed max of each per-run metric\n";
    o << "runs: " << b.runs << "\nrun_indices: [";
    for (std::size_t i = 0; i < b.run_indices.size(); ++i) o << (i ? ", " : "") << b.run_indices[i];
    o << "]\n";
    o << "distance_since_gnss_m: " << agg(b.distance) << "\n";
    o << "final_percent:\n  hor: " << agg(b.hor_pct) << "\n  cross: " << agg(b.cross_pct) << "\n  along: "
      << agg(b.along_pct) << "\n";
    o << "signals:\n";
    for (const auto& info : kSignals) {
        const SignalAggregate& s = b.signals[index(info.signal)];
        o << "  " << info.key << ":\n    mean: " << agg(s.mean) << "\n    std: " << agg(s.std)
          << "\n    max: " << agg(s.max) << "\n    final: " << agg(s.final) << "\n";
    }
    return o.str();
}

}  // namespace gdnav::core::metrics
