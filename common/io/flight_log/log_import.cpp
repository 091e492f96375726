#include "io/flight_log/log_import.hpp"

#include <cmath>
#include <fstream>
#include <memory>
#include <vector>

#include <spdlog/spdlog.h>

#include "config/config.hpp"
#include "io/flight_log/csv_table.hpp"
#include "io/flight_log/log_layout.hpp"
#include "io/flight_log/log_reference.hpp"
#include "io/recording/recording_writer.hpp"
#include "framework/topic_types.hpp"
#include "msgs/messages.hpp"

namespace gdnav::io::flight_log {

namespace fs = std::filesystem;

namespace {

std::string fmt_exact(double v) {
    char b[48];
    std::snprintf(b, sizeof(b), "%.17g", v);
    return b;
}

struct Sample {
    const msg::MessageOps* ops;
    void* p;
    explicit Sample(const msg::MessageOps& o) : ops(&o), p(o.create()) {}
    ~Sample() { ops->destroy(p); }
    Sample(const Sample&) = delete;
    Sample& operator=(const Sample&) = delete;
};

struct LoadedGroup {
    const LogGroup* group;
    CsvTable table;  // column 0 is t_s
};

std::vector<std::string> csv_columns(const std::vector<LogField>& fields, bool with_time) {
    std::vector<std::string> c;
    if (with_time) c.push_back(kTimeColumn);
    for (const auto& f : fields) c.push_back(f.name);
    return c;
}

// Times strictly increasing; continuous signals without gaps above max_gap_s.
void check_times(const LoadedGroup& g, double max_gap_s) {
    const CsvTable& t = g.table;
    for (std::size_t i = 1; i < t.rows(); ++i) {
        const double a = t.at(i - 1, 0), b = t.at(i, 0);
        const std::string where = t.file + ":" + std::to_string(t.lines[i]);
        if (!(b > a)) input_error(where, "column 't_s': " + fmt_t(b) + " s is not after the previous row's " + fmt_t(a) + " s (times must increase)");
        if (!g.group->fixes && b - a > max_gap_s)
            input_error(where, "column 't_s': gap of " + fmt_t(b - a) + " s after t = " + fmt_t(a) + " s (at most " +
                            fmt_t(max_gap_s) + " s, --max-gap)");
    }
}

// Fills a continuous group's sample for grid step k (called for k = 0, 1, ...): linear interpolation of every column
// at the grid instant.
class ContinuousCursor {
public:
    explicit ContinuousCursor(const LoadedGroup& g) : g_(g) {}
    void fill(std::uint64_t k, const ImportOptions& o, Sample& s) {
        const CsvTable& t = g_.table;
        const auto& fields = g_.group->fields;
        const double tk = o.t0_s + static_cast<double>(k) * o.dt_s;
        while (i_ + 1 < t.rows() && t.at(i_ + 1, 0) <= tk) ++i_;
        const double* a = t.row(i_);
        if (std::abs(tk - a[0]) <= kSnapS || i_ + 1 == t.rows()) {
            for (std::size_t c = 0; c < fields.size(); ++c) fields[c].ref(s.p) = a[c + 1];
        } else if (i_ + 1 < t.rows() && std::abs(t.at(i_ + 1, 0) - tk) <= kSnapS) {
            const double* b = t.row(i_ + 1);
            for (std::size_t c = 0; c < fields.size(); ++c) fields[c].ref(s.p) = b[c + 1];
        } else {
            const double* b = t.row(i_ + 1);
            const double u = (tk - a[0]) / (b[0] - a[0]);
            for (std::size_t c = 0; c < fields.size(); ++c) fields[c].ref(s.p) = a[c + 1] + u * (b[c + 1] - a[c + 1]);
        }
    }

private:
    const LoadedGroup& g_;
    std::size_t i_{0};
};

// GNSS: each fix at its nearest step; other steps hold the last fix with fix_valid false.
class FixCursor {
public:
    FixCursor(const LoadedGroup& g, const ImportOptions& o, std::uint64_t steps) : g_(g), fix_row_(steps, -1) {
        const CsvTable& t = g.table;
        for (std::size_t r = 0; r < t.rows(); ++r) {
            const double x = (t.at(r, 0) - o.t0_s) / o.dt_s;
            if (x < -0.5 || x >= static_cast<double>(steps) - 0.5) continue;  // outside the grid
            const auto k = static_cast<std::uint64_t>(std::llround(x));
            if (fix_row_[k] >= 0)
                input_error(t.file + ":" + std::to_string(t.lines[r]),
                     "column 't_s': second fix on grid step " + std::to_string(k) + " (line " +
                         std::to_string(t.lines[static_cast<std::size_t>(fix_row_[k])]) + "): fixes closer than dt");
            fix_row_[k] = static_cast<std::int64_t>(r);
            ++placed_;
        }
    }
    void fill(std::uint64_t k, Sample& s) {
        const bool fix = fix_row_[k] >= 0;
        if (fix) {
            const double* a = g_.table.row(static_cast<std::size_t>(fix_row_[k]));
            for (std::size_t c = 0; c < g_.group->fields.size(); ++c) g_.group->fields[c].ref(s.p) = a[c + 1];
        }
        g_.group->fix_valid(s.p) = fix;
    }
    [[nodiscard]] std::uint64_t placed() const { return placed_; }

private:
    const LoadedGroup& g_;
    std::vector<std::int64_t> fix_row_;
    std::uint64_t placed_{0};
};

void check_options(const ImportOptions& o) {
    if (!(o.dt_s > 0.0) || !std::isfinite(o.dt_s)) input_error("--dt", "must be a positive number of seconds");
    if (!std::isfinite(o.t0_s)) input_error("--t0", "must be a finite time in seconds");
    if (!(o.max_gap_s > 0.0)) input_error("--max-gap", "must be positive");
    std::error_code ec;
    if (!fs::is_directory(o.csv_dir, ec)) input_error(o.csv_dir.string(), "not a directory");
}

// The sensor files present in the folder, read and checked.
std::vector<LoadedGroup> load_groups(const ImportOptions& o) {
    std::error_code ec;
    std::vector<LoadedGroup> loaded;
    std::string names;
    for (const LogGroup& g : log_groups()) {
        names += (names.empty() ? "" : ", ") + g.name + ".csv";
        const fs::path f = o.csv_dir / (g.name + ".csv");
        if (!fs::exists(f, ec)) continue;
        loaded.push_back({&g, read_csv(f, csv_columns(g.fields, true))});
        check_times(loaded.back(), o.max_gap_s);
    }
    if (loaded.empty()) input_error(o.csv_dir.string(), "no sensor file (" + names + ")");
    return loaded;
}

// The grid: must start inside every continuous signal and, by default, ends where the first of them ends.
std::uint64_t grid_steps(const std::vector<LoadedGroup>& loaded, const ImportOptions& o) {
    std::optional<std::uint64_t> covered;
    for (const auto& g : loaded) {
        if (g.group->fixes) continue;
        const CsvTable& t = g.table;
        const double first = t.at(0, 0), last = t.at(t.rows() - 1, 0);
        if (first > o.t0_s + kSnapS)
            input_error(t.file + ":" + std::to_string(t.lines[0]),
                 "column 't_s': first sample at t = " + fmt_t(first) + " s, after the grid start --t0 " + fmt_t(o.t0_s) + " s");
        const double n = std::floor((last - o.t0_s + kSnapS) / o.dt_s) + 1.0;
        const auto steps = static_cast<std::uint64_t>(n);
        if (!covered || steps < *covered) covered = steps;
        if (o.steps && *o.steps > steps)
            input_error(t.file + ":" + std::to_string(t.lines.back()),
                 "column 't_s': last sample at t = " + fmt_t(last) + " s, before the last grid step t = " +
                     fmt_t(o.t0_s + static_cast<double>(*o.steps - 1) * o.dt_s) + " s of --steps " +
                     std::to_string(*o.steps));
    }
    std::uint64_t steps = o.steps ? *o.steps : covered.value_or(0);
    if (!o.steps && !covered) {  // GNSS only: up to the last fix
        const CsvTable& t = loaded.front().table;
        steps = static_cast<std::uint64_t>(std::max(0.0, std::llround((t.at(t.rows() - 1, 0) - o.t0_s) / o.dt_s) + 1.0));
    }
    if (steps == 0) input_error("--steps", "the grid has no step");
    return steps;
}

// alignment.csv (constant over the run), when the folder has one.
std::optional<CsvTable> load_alignment(const ImportOptions& o) {
    const AlignmentLayout& al = alignment_layout();
    const fs::path align_file = o.csv_dir / kAlignmentFile;
    std::error_code ec;
    if (!fs::exists(align_file, ec)) {
        spdlog::warn("import-log: no {}: the align_* fields are zero, so run the filters with init_mode: measurements "
                     "(--set components.nav_att.init_mode=measurements --set components.nav_pos.init_mode=measurements)",
                     align_file.string());
        return std::nullopt;
    }
    std::vector<std::string> cols = csv_columns(al.imu, false);
    for (const auto& c : csv_columns(al.mag, false)) cols.push_back(c);
    CsvTable align = read_csv(align_file, cols);
    if (align.rows() != 1)
        input_error(align.file + ":" + std::to_string(align.lines[1]), "one data row expected (the alignment at t0)");
    return align;
}

// One group's sample being filled step by step.
struct Track {
    const LoadedGroup* g;
    std::unique_ptr<Sample> s;
    std::optional<ContinuousCursor> continuous;
    std::optional<FixCursor> fixes;
};

std::vector<Track> make_tracks(const std::vector<LoadedGroup>& loaded, const std::optional<CsvTable>& align,
                               const ImportOptions& o, std::uint64_t steps) {
    const AlignmentLayout& al = alignment_layout();
    std::vector<Track> tracks;
    for (const auto& g : loaded) {
        Track tr{&g, std::make_unique<Sample>(*framework::find_topic(g.group->topic)), {}, {}};
        if (align && g.group->name == "imu")
            for (std::size_t c = 0; c < al.imu.size(); ++c) al.imu[c].ref(tr.s->p) = align->at(0, c);
        if (align && g.group->name == "mag")
            for (std::size_t c = 0; c < al.mag.size(); ++c) al.mag[c].ref(tr.s->p) = align->at(0, al.imu.size() + c);
        if (g.group->fixes) tr.fixes.emplace(g, o, steps);
        else tr.continuous.emplace(g);
        tracks.push_back(std::move(tr));
    }
    return tracks;
}

// One recording, the groups interleaved step by step (log-time order, as the recorder writes).
void write_recording(const fs::path& record_dir, const std::vector<std::string>& topics, std::vector<Track>& tracks,
                     ReferenceTrack* reference, const ImportOptions& o, std::uint64_t steps) {
    recording::RecordingOptions ro;
    ro.t0_s = o.t0_s;
    ro.dt_s = o.dt_s;
    ro.run_metadata = {{"source", "gdnav import-log " + fs::absolute(o.csv_dir).string()},
                       {"t0_s", fmt_exact(o.t0_s)},
                       {"dt_s", fmt_exact(o.dt_s)},
                       {"steps", std::to_string(steps)},
                       {"step_ns", std::to_string(recording::step_ns(o.dt_s))},
                       {"log_time_epoch", "t0_s: log_time = publish_time = step * step_ns ns; t_s = t0_s + step * dt_s"}};
    try {
        recording::RecordingWriter w(record_dir, topics, ro);
        for (std::uint64_t k = 0; k < steps; ++k) {
            const double tk = o.t0_s + static_cast<double>(k) * o.dt_s;
            for (std::size_t i = 0; i < tracks.size(); ++i) {
                Track& tr = tracks[i];
                if (tr.fixes) tr.fixes->fill(k, *tr.s);
                else tr.continuous->fill(k, o, *tr.s);
                tr.s->ops->set_stamp(tr.s->p, 0, k, tk);
                w.append(i, k, tr.s->p);
            }
            if (reference) {
                msg::Truth truth;
                reference->fill(k, truth);
                msg::message_ops<msg::Truth>().set_stamp(&truth, 0, k, tk);
                w.append(tracks.size(), k, &truth);
            }
        }
        w.close(true);
    } catch (const std::runtime_error& e) {
        if (dynamic_cast<const config::ConfigError*>(&e)) throw;
        input_error(record_dir.string(), e.what());
    }
}

// The per-file log lines and <run_dir>/import.yaml.
void report_import(const std::vector<Track>& tracks, const ReferenceTrack* reference,
                   const std::vector<std::string>& topics, bool aligned, const ImportOptions& o, std::uint64_t steps,
                   const fs::path& record_dir) {
    for (const auto& tr : tracks) {
        if (tr.fixes)
            spdlog::info("import-log: {}: {} rows, {} fixes on the grid -> {}", tr.g->table.file, tr.g->table.rows(),
                         tr.fixes->placed(), tr.g->group->topic);
        else
            spdlog::info("import-log: {}: {} rows -> {}", tr.g->table.file, tr.g->table.rows(), tr.g->group->topic);
    }
    if (reference)
        spdlog::info("import-log: reference {}: {} rows ({}) -> {}", reference->file(), reference->rows(),
                     reference->form(), topics::kTruth);
    else
        spdlog::info("import-log: no --reference: a replay of this log has no true trajectory and writes no error "
                     "metrics (metrics.yaml reference: none; docs/replay.md)");
    std::ofstream info(o.run_dir / "import.yaml");
    char grid[160];
    std::snprintf(grid, sizeof(grid), "t0_s: %.17g\ndt_s: %.17g\nsteps: %llu\n", o.t0_s, o.dt_s,
                  static_cast<unsigned long long>(steps));
    info << "# written by gdnav import-log (docs/replay.md)\nsource: \"" << fs::absolute(o.csv_dir).string() << "\"\n"
         << grid << "alignment: " << (aligned ? "true" : "false") << "\n";
    if (reference) info << "reference: \"" << fs::absolute(reference->file()).string() << "\"\n";
    info << "topics: [";
    for (std::size_t i = 0; i < topics.size(); ++i) info << (i ? ", " : "") << topics[i];
    info << "]\n";
    spdlog::info("import-log: {} steps of {} s from t0 = {} s (t = {} .. {} s) written to {}", steps, o.dt_s, o.t0_s,
                 fmt_t(o.t0_s), fmt_t(o.t0_s + static_cast<double>(steps - 1) * o.dt_s), record_dir.string());
}

}  // namespace

void import_log(const ImportOptions& o) {
    check_options(o);
    const std::vector<LoadedGroup> loaded = load_groups(o);
    const std::uint64_t steps = grid_steps(loaded, o);
    const std::optional<CsvTable> align = load_alignment(o);
    const fs::path record_dir = o.run_dir / "record";
    std::vector<std::string> topics;
    for (const auto& g : loaded) topics.push_back(g.group->topic);
    std::vector<Track> tracks = make_tracks(loaded, align, o, steps);
    std::optional<ReferenceTrack> reference;
    if (o.reference) {
        reference.emplace(*o.reference, o, steps);
        topics.push_back(topics::kTruth);
    }
    write_recording(record_dir, topics, tracks, reference ? &*reference : nullptr, o, steps);
    report_import(tracks, reference ? &*reference : nullptr, topics, align.has_value(), o, steps, record_dir);
}

}  // namespace gdnav::io::flight_log
