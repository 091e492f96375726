#include "metrics/run_record.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "config/config.hpp"
#include "files/write_error.hpp"

namespace gdnav::core::metrics {

namespace fs = std::filesystem;

std::string format_double17(double v) {
    if (std::isnan(v)) return ".nan";
    if (std::isinf(v)) return v > 0 ? ".inf" : "-.inf";
    char buf[40];
    std::snprintf(buf, sizeof(buf), "%.17g", v);
    return buf;
}

RunRecord make_run_record(const RunMetrics& m, bool complete, std::uint64_t seed, std::uint64_t run_index,
                          std::uint64_t steps) {
    RunRecord r{.complete = complete, .seed = seed, .run_index = run_index, .steps = steps, .t_gnss_s = m.t_gnss_s()};
    r.t_end_s = m.t_last_s();
    r.samples = m.stats(Signal::yaw).count();
    r.distance_m = m.distance_since_gnss_m();
    r.hor_pct = m.final_percent(Signal::hor);
    r.cross_pct = m.final_percent(Signal::cross);
    r.along_pct = m.final_percent(Signal::along);
    r.att_trend_from_s = m.t_att_trend_s();
    r.att_slope_rad_per_s = m.att_trend().slope();
    r.hor_slope_mps = m.hor_trend().slope();
    r.hor_r2 = m.hor_trend().r2();
    for (const auto& info : kSignals) {
        const RunningStats& s = m.stats(info.signal);
        r.signals[index(info.signal)] = {s.mean(), s.std(), s.smax(), s.last()};
    }
    r.estimates_complete = m.estimates_complete();
    r.distance_t_end_m = r.estimates_complete ? r.distance_m : m.distance_at_t_last_m();
    for (std::size_t i = 0; i < kEstimateCount; ++i) r.last_estimate_s[i] = m.last_estimate_s(static_cast<Estimate>(i));
    return r;
}

RunRecord make_unreferenced_record(bool complete, std::uint64_t seed, std::uint64_t run_index, std::uint64_t steps,
                                   double t_gnss_s) {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    RunRecord r{.complete = complete, .seed = seed, .run_index = run_index, .steps = steps, .t_gnss_s = t_gnss_s,
                .has_reference = false};
    r.t_end_s = r.distance_m = r.distance_t_end_m = r.hor_pct = r.cross_pct = r.along_pct = kNaN;
    r.att_trend_from_s = r.att_slope_rad_per_s = r.hor_slope_mps = r.hor_r2 = kNaN;
    r.signals.fill({kNaN, kNaN, kNaN, kNaN});
    r.last_estimate_s.fill(kNaN);
    return r;
}

std::string to_yaml(const RunRecord& r) {
    std::ostringstream o;
    auto d = [](double v) { return format_double17(v); };
    if (!r.has_reference) {
        o << "# gdnav per-run record (nav_recorder): no reference trajectory, so no error metrics; docs/replay.md\n";
        o << "complete: " << (r.complete ? "true" : "false") << "\nreference: none\n";
        o << "seed: " << r.seed << "\nrun_index: " << r.run_index << "\nsteps: " << r.steps << "\n";
        o << "t_gnss_s: " << d(r.t_gnss_s) << "\n";
        return o.str();
    }
    o << "# gdnav per-run navigation metrics (nav_recorder); SI units, window t in [0, t_end]; docs/montecarlo.md\n";
    if (!r.estimates_complete)
        o << "# an estimator stopped before the end (last_estimate_s): final = at t_end, % of the distance up to t_end\n";
    o << "complete: " << (r.complete ? "true" : "false") << "\n";
    if (!r.estimates_complete) o << "estimates_complete: false\n";
    o << "seed: " << r.seed << "\nrun_index: " << r.run_index << "\nsteps: " << r.steps << "\n";
    o << "t_gnss_s: " << d(r.t_gnss_s) << "\nt_end_s: " << d(r.t_end_s) << "\nsamples: " << r.samples << "\n";
    o << "distance_since_gnss_m: " << d(r.distance_m) << "\n";
    if (!r.estimates_complete) o << "distance_at_t_end_m: " << d(r.distance_t_end_m) << "\n";
    o << "final_percent: {hor: " << d(r.hor_pct) << ", cross: " << d(r.cross_pct) << ", along: " << d(r.along_pct)
      << "}\n";
    if (!r.estimates_complete) {
        o << "last_estimate_s: {";
        for (std::size_t i = 0; i < kEstimateCount; ++i)
            o << (i ? ", " : "") << kEstimateKeys[i] << ": " << d(r.last_estimate_s[i]);
        o << "}\n";
    }
    o << "trends: {att_from_s: " << d(r.att_trend_from_s) << ", att_slope_rad_per_s: " << d(r.att_slope_rad_per_s)
      << ", hor_slope_mps: " << d(r.hor_slope_mps) << ", hor_r2: " << d(r.hor_r2) << "}\n";
    o << "signals:\n";
    for (const auto& info : kSignals) {
        const SignalSummary& s = r.signals[index(info.signal)];
        o << "  " << info.key << ": {mean: " << d(s.mean) << ", std: " << d(s.std) << ", max: " << d(s.max)
          << ", final: " << d(s.final) << "}\n";
    }
    return o.str();
}

void write_run_record(const fs::path& file, const RunRecord& r) { files::write_whole(file, to_yaml(r)); }

namespace {

double read_double(const config::Config& c, const char* key) {
    const YAML::Node n = c.node()[key];
    if (!n || !n.IsScalar()) c.fail(key, "missing: a number is required");
    const std::string s = n.Scalar();
    if (s == ".nan" || s == ".NaN" || s == ".NAN") return std::numeric_limits<double>::quiet_NaN();
    return c.get_double(key);
}

}  // namespace

RunRecord read_run_record(const fs::path& file) {
    const config::Config c = config::Config::load(file);
    if (c.has("reference"))
        c.fail("reference", "'" + c.get_string("reference") +
                                "': the run had no reference trajectory, so it has no error metrics (docs/replay.md)");
    RunRecord r;
    r.complete = c.get_bool("complete");
    r.seed = c.get_uint64("seed");
    r.run_index = c.get_uint64("run_index");
    r.steps = c.get_uint64("steps");
    r.t_gnss_s = read_double(c, "t_gnss_s");
    r.t_end_s = read_double(c, "t_end_s");
    r.samples = c.get_uint64("samples");
    r.distance_m = read_double(c, "distance_since_gnss_m");
    const config::Config pct = c.child("final_percent");
    r.hor_pct = read_double(pct, "hor");
    r.cross_pct = read_double(pct, "cross");
    r.along_pct = read_double(pct, "along");
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    r.att_trend_from_s = r.att_slope_rad_per_s = r.hor_slope_mps = r.hor_r2 = kNaN;
    if (c.has("trends")) {
        const config::Config tr = c.child("trends");
        r.att_trend_from_s = read_double(tr, "att_from_s");
        r.att_slope_rad_per_s = read_double(tr, "att_slope_rad_per_s");
        r.hor_slope_mps = read_double(tr, "hor_slope_mps");
        r.hor_r2 = read_double(tr, "hor_r2");
    }
    r.estimates_complete = c.get_bool("estimates_complete", true);
    r.distance_t_end_m = r.estimates_complete ? r.distance_m : read_double(c, "distance_at_t_end_m");
    r.last_estimate_s.fill(kNaN);
    if (!r.estimates_complete) {
        const config::Config le = c.child("last_estimate_s");
        for (std::size_t i = 0; i < kEstimateCount; ++i)
            r.last_estimate_s[i] = read_double(le, std::string(kEstimateKeys[i]).c_str());
    }
    const config::Config sig = c.child("signals");
    for (const auto& info : kSignals) {
        const config::Config s = sig.child(info.key);
        r.signals[index(info.signal)] = {read_double(s, "mean"), read_double(s, "std"), read_double(s, "max"),
                                         read_double(s, "final")};
    }
    return r;
}

bool run_record_complete(const fs::path& file) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) return false;
    try {
        const config::Config c = config::Config::load(file);
        return c.get_bool("complete", false);
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace gdnav::core::metrics
