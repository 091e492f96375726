#include "io/flight_log/log_export.hpp"

#include <cmath>
#include <memory>
#include <vector>

#include <spdlog/spdlog.h>

#include "config/config.hpp"
#include "io/flight_log/csv_table.hpp"
#include "io/flight_log/log_layout.hpp"
#include "io/flight_log/log_reference.hpp"
#include "msgs/messages.hpp"
#include "io/recording/record_file.hpp"

namespace gdnav::io::flight_log {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& what) {
    throw config::ConfigError("config error: " + where + ": " + what);
}

using SamplePtr = std::unique_ptr<void, void (*)(void*)>;

// A record decoded sample by sample.
class RecordSamples {
public:
    RecordSamples(recording::TopicRecord r) : r_(std::move(r)), dec_(*r_.ops), s_(r_.ops->create(), r_.ops->destroy) {}
    [[nodiscard]] std::size_t size() const { return r_.entries.size(); }
    [[nodiscard]] std::uint64_t step(std::size_t i) const { return r_.entries[i].step; }
    void* load(std::size_t i) {
        const auto& e = r_.entries[i];
        if (!dec_.decode(&r_.bytes[e.offset], e.size, s_.get()))
            fail(r_.file.string(), "cannot decode the sample of step " + std::to_string(e.step));
        return s_.get();
    }

private:
    recording::TopicRecord r_;
    recording::SampleDecoder dec_;
    SamplePtr s_;
};

// Steps between exported rows for `rate_hz` on a grid of dt_s.
std::uint64_t decimation(const std::string& group, double rate_hz, double dt_s) {
    const double x = 1.0 / (rate_hz * dt_s);
    const double d = std::round(x);
    if (d < 1.0 || std::abs(x - d) > 1e-6 * d)
        fail("--rates", group + "=" + std::to_string(rate_hz) + " Hz is not the grid rate (" + std::to_string(1.0 / dt_s) +
                            " Hz) divided by a whole number");
    return static_cast<std::uint64_t>(d);
}

void check_rates(const ExportOptions& o) {
    for (const auto& [name, rate] : o.rates_hz) {
        bool known = false;
        for (const auto& g : log_groups()) known = known || g.name == name;
        if (!known) fail("--rates", "unknown sensor group '" + name + "' (known: imu, mag, air, atm, gnss)");
        if (!(rate > 0.0) || !std::isfinite(rate)) fail("--rates", name + ": the rate must be positive (Hz)");
    }
}

// Every channel of <run_dir>/record: a foreign one is refused.
recording::Recording read_record(const fs::path& record_dir, const ExportOptions& o) {
    std::error_code ec;
    if (!fs::is_directory(record_dir, ec)) fail(o.run_dir.string(), "no record/ directory (record the run with --record)");
    try {
        return recording::read_recording(record_dir);
    } catch (const std::runtime_error& e) {
        fail("export-log", e.what());
    }
}

// Writes <csv_dir>/<group>.csv from the group's record at its rate; returns its alignment values (imu, mag: those of
// the first sample; other groups: none).
std::vector<double> export_group(const LogGroup& g, RecordSamples& rec, const recording::Recording& recording,
                                 const ExportOptions& o) {
    if (rec.size() == 0) fail(recording.file.string() + ": " + g.topic, "no samples");
    // The grid step from the stamps of the first and last samples.
    const double t_first = g.t_s(rec.load(0));
    double dt_s = 0.01;
    if (rec.size() > 1) {
        const double t_last = g.t_s(rec.load(rec.size() - 1));
        dt_s = (t_last - t_first) / static_cast<double>(rec.step(rec.size() - 1) - rec.step(0));
    }
    const auto it = o.rates_hz.find(g.name);
    const std::uint64_t every = it == o.rates_hz.end() ? 1 : decimation(g.name, it->second, dt_s);

    std::vector<std::string> columns{kTimeColumn};
    for (const auto& f : g.fields) columns.push_back(f.name);
    CsvWriter csv(o.csv_dir / (g.name + ".csv"), columns);
    std::vector<double> row(columns.size());
    std::uint64_t rows = 0;
    for (std::size_t i = 0; i < rec.size(); ++i) {
        if (rec.step(i) % every != 0) continue;
        void* s = rec.load(i);
        if (g.fix_valid && !g.fix_valid(s)) continue;
        row[0] = g.t_s(s);
        for (std::size_t c = 0; c < g.fields.size(); ++c) row[c + 1] = g.fields[c].ref(s);
        csv.row(row);
        ++rows;
    }
    try {
        csv.close();
    } catch (const std::runtime_error& e) {
        fail("export-log", e.what());
    }
    spdlog::info("export-log: {} -> {}.csv: {} rows (every {} steps{})", g.topic, g.name, rows, every,
                 g.fixes ? ", valid fixes only" : "");
    const AlignmentLayout& al = alignment_layout();
    std::vector<double> align;
    if (g.name == "imu")
        for (const auto& f : al.imu) align.push_back(f.ref(rec.load(0)));
    if (g.name == "mag")
        for (const auto& f : al.mag) align.push_back(f.ref(rec.load(0)));
    return align;
}

void write_alignment(const std::vector<double>& imu_align, const std::vector<double>& mag_align,
                     const ExportOptions& o) {
    if (imu_align.empty() || mag_align.empty()) {
        spdlog::info("export-log: no {} (needs records of both ImuSample and MagSample)", kAlignmentFile);
        return;
    }
    const AlignmentLayout& al = alignment_layout();
    std::vector<std::string> columns;
    for (const auto& f : al.imu) columns.push_back(f.name);
    for (const auto& f : al.mag) columns.push_back(f.name);
    std::vector<double> row = imu_align;
    row.insert(row.end(), mag_align.begin(), mag_align.end());
    CsvWriter csv(o.csv_dir / kAlignmentFile, columns);
    csv.row(row);
    csv.close();
    spdlog::info("export-log: alignment of the first ImuSample and MagSample -> {}", kAlignmentFile);
}

// A recorded Truth -> reference.csv at every step: the reference trajectory for `import-log --reference`.
void export_reference(RecordSamples& rec, const ExportOptions& o) {
    CsvWriter csv(o.csv_dir / kReferenceFile, reference_columns());
    for (std::size_t i = 0; i < rec.size(); ++i) csv.row(reference_row(*static_cast<const msg::Truth*>(rec.load(i))));
    try {
        csv.close();
    } catch (const std::runtime_error& e) {
        fail("export-log", e.what());
    }
    spdlog::info("export-log: {} -> {}: {} rows (every step; the reference for import-log --reference)",
                 topics::kTruth, kReferenceFile, rec.size());
}

}  // namespace

void export_log(const ExportOptions& o) {
    check_rates(o);
    const fs::path record_dir = o.run_dir / "record";
    recording::Recording recording = read_record(record_dir, o);
    fs::create_directories(o.csv_dir);
    std::vector<double> imu_align, mag_align;
    int written = 0;
    for (const LogGroup& g : log_groups()) {
        auto found = recording.topics.find(g.topic);
        if (found == recording.topics.end()) {
            spdlog::info("export-log: no record of {}: no {}.csv", g.topic, g.name);
            continue;
        }
        auto rec = std::make_unique<RecordSamples>(std::move(found->second));
        const std::vector<double> align = export_group(g, *rec, recording, o);
        if (g.name == "imu") imu_align = align;
        if (g.name == "mag") mag_align = align;
        ++written;
    }
    if (written == 0) fail(record_dir.string(), "no record of a sensor topic (ImuSample, MagSample, AirSample, AtmSample, GnssSample)");
    write_alignment(imu_align, mag_align, o);
    auto truth = recording.topics.find(topics::kTruth);
    if (truth != recording.topics.end()) {
        RecordSamples rec(std::move(truth->second));
        export_reference(rec, o);
    } else {
        spdlog::info("export-log: no record of {}: no {}", topics::kTruth, kReferenceFile);
    }
}

}  // namespace gdnav::io::flight_log
