#include "metrics/report_tables.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "math/rotation.hpp"

namespace gdnav::core::metrics {

namespace {

constexpr double kRad2Deg = 180.0 / math::kPi;

enum class Row { mean, std, max };
const char* row_name(Row r) { return r == Row::mean ? "mean" : r == Row::std ? "std" : "max"; }
double value(const Aggregate& a, Row r) { return r == Row::mean ? a.mean : r == Row::std ? a.std : a.max; }
// A signed quantity prints its sign in the mean and max rows only (the std of anything is a magnitude).
bool signed_in(Row r, bool signed_quantity) { return signed_quantity && r != Row::std; }

std::string cell(const Aggregate& a, Row r, double scale, int decimals, bool signed_quantity) {
    return fixed(value(a, r) * scale, decimals, signed_in(r, signed_quantity));
}

constexpr Row kRows[] = {Row::mean, Row::std, Row::max};

// Attitude-like table: per signal the aggregated per-run mean and std (and max for the norm).
void mean_std_table(std::ostringstream& o, const std::vector<LabelledBatch>& bs, const std::string& title,
                    const std::vector<std::pair<Signal, std::string>>& cols, const std::vector<double>& scales,
                    int decimals, bool norm_max_last) {
    o << "### " << title << "\n\n| Scenario | |";
    for (std::size_t i = 0; i < cols.size(); ++i) {
        const bool with_max = norm_max_last && i + 1 == cols.size();
        o << " " << cols[i].second << " mean | " << cols[i].second << " std |";
        if (with_max) o << " " << cols[i].second << " max\\|·\\| |";
    }
    o << "\n|---|---|";
    for (std::size_t i = 0; i < cols.size(); ++i) o << (norm_max_last && i + 1 == cols.size() ? "--:|--:|--:|" : "--:|--:|");
    o << "\n";
    for (const auto& b : bs) {
        for (Row r : kRows) {
            o << "| " << (r == Row::mean ? b.label : "") << " | " << row_name(r) << " |";
            for (std::size_t i = 0; i < cols.size(); ++i) {
                const bool is_norm = norm_max_last && i + 1 == cols.size();
                const SignalAggregate& s = b.aggregate[cols[i].first];
                o << " " << cell(s.mean, r, scales[i], decimals, !is_norm) << " | "
                  << cell(s.std, r, scales[i], decimals, false) << " |";
                if (is_norm) o << " " << cell(s.max, r, scales[i], decimals, false) << " |";
            }
            o << "\n";
        }
    }
    o << "\n";
}

// Final-value table: one column per (batch, signal).
void final_table(std::ostringstream& o, const std::vector<LabelledBatch>& bs, const std::string& title,
                 const std::string& corner, const std::vector<std::pair<Signal, std::string>>& cols, int decimals) {
    o << "### " << title << "\n\n| " << corner << " |";
    for (const auto& b : bs)
        for (const auto& c : cols) o << " " << b.label << (c.second.empty() ? "" : " " + c.second) << " |";
    o << "\n|---|";
    for (std::size_t i = 0; i < bs.size() * cols.size(); ++i) o << "--:|";
    o << "\n";
    for (Row r : kRows) {
        o << "| " << row_name(r) << " |";
        for (const auto& b : bs)
            for (const auto& c : cols) o << " " << cell(b.aggregate[c.first].final, r, 1.0, decimals, true) << " |";
        o << "\n";
    }
    o << "\n";
}

void horizontal_table(std::ostringstream& o, const std::vector<LabelledBatch>& bs) {
    o << "### Aggregated final horizontal position NSE\n\n"
         "| Scenario | | Distance [m] | Δx_cross(t_end) [m] | [%] | Δx_along(t_end) [m] | [%] | Δx_hor(t_end) [m] | [%] |\n"
         "|---|---|--:|--:|--:|--:|--:|--:|--:|\n";
    for (const auto& b : bs) {
        const auto& a = b.aggregate;
        for (Row r : kRows) {
            o << "| " << (r == Row::mean ? b.label : "") << " | " << row_name(r) << " | "
              << cell(a.distance, r, 1.0, 0, false) << " | " << cell(a[Signal::cross].final, r, 1.0, 0, true) << " | "
              << cell(a.cross_pct, r, 1.0, 2, true) << " | " << cell(a[Signal::along].final, r, 1.0, 0, true)
              << " | " << cell(a.along_pct, r, 1.0, 2, true) << " | " << cell(a[Signal::hor].final, r, 1.0, 0, false)
              << " | " << cell(a.hor_pct, r, 1.0, 2, false) << " |\n";
        }
    }
    o << "\n";
}

void trajectory_table(std::ostringstream& o, const std::vector<LabelledBatch>& bs) {
    o << "### Trajectory metrics of the vertical and ground speed errors (not a table of the paper)\n\n"
         "| Scenario | | ĥ−h mean [m] | std | max | v̂_N−v_N mean [m/s] | std | max | v̂_E−v_E mean [m/s] | std | max |\n"
         "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
    for (const auto& b : bs)
        for (Row r : kRows) {
            o << "| " << (r == Row::mean ? b.label : "") << " | " << row_name(r) << " |";
            for (Signal s : {Signal::h, Signal::vn, Signal::ve}) {
                const SignalAggregate& a = b.aggregate[s];
                o << " " << cell(a.mean, r, 1.0, 2, true) << " | " << cell(a.std, r, 1.0, 2, false) << " | "
                  << cell(a.max, r, 1.0, 2, r == Row::max) << " |";
            }
            o << "\n";
        }
    o << "\n";
}

void runs_table(std::ostringstream& o, const LabelledBatch& b) {
    if (b.runs.empty()) return;
    std::vector<const RunRecord*> by_hor, by_att;
    for (const auto& r : b.runs) {
        by_hor.push_back(&r);
        by_att.push_back(&r);
    }
    auto key_hor = [](const RunRecord* r) { return std::isfinite(r->signals[index(Signal::hor)].final) ? r->signals[index(Signal::hor)].final : 1e300; };
    auto key_att = [](const RunRecord* r) { return std::isfinite(r->signals[index(Signal::rot)].mean) ? r->signals[index(Signal::rot)].mean : 1e300; };
    std::stable_sort(by_hor.begin(), by_hor.end(), [&](auto* a, auto* c) { return key_hor(a) < key_hor(c); });
    std::stable_sort(by_att.begin(), by_att.end(), [&](auto* a, auto* c) { return key_att(a) < key_att(c); });
    auto line = [](const char* what, const RunRecord* r) {
        std::string s = std::string("| ") + what + " | " + std::to_string(r->run_index);
        if (!r->estimates_complete) s += " (estimates stop at t = " + fixed(r->t_end_s, 2, false) + " s)";
        s += " | ";
        s += fixed(r->signals[index(Signal::rot)].mean * kRad2Deg, 3, false) + " | ";
        s += fixed(r->signals[index(Signal::h)].final, 2, true) + " | ";
        s += fixed(r->signals[index(Signal::hor)].final, 0, false) + " | " + fixed(r->hor_pct, 2, false) + " | ";
        s += fixed(r->final_distance_m(), 0, false) + " |\n";
        return s;
    };
    o << "### Best and worst runs, " << b.label << "\n\n"
      << "| ranking | run | ‖Δr‖ mean [deg] | ĥ−h final [m] | Δx_hor final [m] | [%] | distance [m] |\n"
      << "|---|--:|--:|--:|--:|--:|--:|\n";
    o << line("best attitude (lowest ‖Δr‖ mean)", by_att.front()) << line("worst attitude", by_att.back());
    o << line("best horizontal (lowest final Δx_hor)", by_hor.front()) << line("worst horizontal", by_hor.back());
    o << "\n";
}

}  // namespace

std::string fixed(double v, int decimals, bool sign) {
    if (!std::isfinite(v)) return "n/a";
    // Values that round to zero print as the paper's "+0.000" / "0.000", never "-0.000".
    if (std::fabs(v) < 0.5 * std::pow(10.0, -decimals)) v = 0.0;
    char buf[64];
    std::snprintf(buf, sizeof(buf), sign ? "%+.*f" : "%.*f", decimals, v);
    return buf;
}

std::string paper_tables_markdown(const std::vector<LabelledBatch>& bs, const std::string& preamble) {
    std::ostringstream o;
    o << preamble << "\n";
    mean_std_table(o, bs, "Aggregated body attitude NSE [deg]",
                   {{Signal::yaw, "ψ̂−ψ"}, {Signal::pitch, "θ̂−θ"}, {Signal::bank, "ξ̂−ξ"}, {Signal::rot, "‖Δr̂‖"}},
                   {kRad2Deg, kRad2Deg, kRad2Deg, kRad2Deg}, 3, true);
    final_table(o, bs, "Aggregated final vertical position (geometric altitude) NSE", "ĥ(t_end) − h(t_end) [m]",
                {{Signal::h, ""}}, 2);
    final_table(o, bs, "Aggregated final ground speed NSE", "v̂(t_end) − v(t_end) [m/s]",
                {{Signal::vn, "v̂_N−v_N"}, {Signal::ve, "v̂_E−v_E"}}, 2);
    horizontal_table(o, bs);
    mean_std_table(o, bs, "Aggregated air data NSE (TAS [m/s], AOA and AOS [deg], ΔT [K]; not a table of the paper)",
                   {{Signal::tas, "v̂_TAS−v_TAS"}, {Signal::aoa, "α̂−α"}, {Signal::aos, "β̂−β"}, {Signal::dT, "ΔT̂−ΔT"}},
                   {1.0, kRad2Deg, kRad2Deg, 1.0}, 3, false);
    trajectory_table(o, bs);
    for (const auto& b : bs) runs_table(o, b);
    return o.str();
}

std::string runs_csv(const std::vector<RunRecord>& runs) {
    std::ostringstream o;
    auto csv = [](double v) { return std::isfinite(v) ? format_double17(v) : std::string(std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf"); };
    o << "run_index,seed,complete,samples,t_end_s,distance_since_gnss_m,hor_pct,cross_pct,along_pct";
    for (const auto& info : kSignals)
        for (const char* stat : {"mean", "std", "max", "final"}) o << "," << info.key << "_" << stat;
    o << ",estimates_complete,distance_at_t_end_m\n";
    for (const auto& r : runs) {
        o << r.run_index << "," << r.seed << "," << (r.complete ? 1 : 0) << "," << r.samples << ","
          << csv(r.t_end_s) << "," << csv(r.distance_m) << "," << csv(r.hor_pct)
          << "," << csv(r.cross_pct) << "," << csv(r.along_pct);
        for (const auto& s : r.signals)
            o << "," << csv(s.mean) << "," << csv(s.std) << "," << csv(s.max) << ","
              << csv(s.final);
        o << "," << (r.estimates_complete ? 1 : 0) << "," << csv(r.final_distance_m()) << "\n";
    }
    return o.str();
}

}  // namespace gdnav::core::metrics
