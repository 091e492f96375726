#include "nav_recorder.hpp"

#include <signal.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <limits>
#include <memory>
#include <optional>

#include <spdlog/spdlog.h>

#include "files/write_error.hpp"
#include "h5_file.hpp"
#include "metrics/run_metrics.hpp"
#include "metrics/run_record.hpp"
#include "msgs/alignment_messages.hpp"
#include "msgs/messages.hpp"
#include "io/run_series/series_columns.hpp"

namespace gdnav::nav_recorder {

namespace fs = std::filesystem;
using config::Range;

namespace {

constexpr std::int64_t kFormatVersion = 1;

// Holds SIGINT/SIGTERM while the file is being updated: a process without handlers (the direct layout) then dies
// after the update, never in the middle of it. (SIGKILL cannot be held; the window it can hit is one update.)
class SignalHold {
public:
    SignalHold() {
        sigset_t hold;
        sigemptyset(&hold);
        sigaddset(&hold, SIGINT);
        sigaddset(&hold, SIGTERM);
        pthread_sigmask(SIG_BLOCK, &hold, &previous_);
    }
    ~SignalHold() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }
    SignalHold(const SignalHold&) = delete;
    SignalHold& operator=(const SignalHold&) = delete;

private:
    sigset_t previous_{};
};

class NavRecorder final : public framework::Component {
public:
    using Component::Component;
    ~NavRecorder() override {
        // finish() not called (an exception unwound the run): leave a consistent file marked incomplete.
        try {
            if (file_ && file_->open()) file_->close();
        } catch (const std::exception&) {
        }
    }

    void configure(const config::Config& cfg, const framework::RunInfo& run, rnd::Stream&) override {
        run_ = run;
        const double t_gnss = cfg.get_double("t_gnss_s", 100.0, Range{-1e6, 1e7});
        const double t_start = cfg.get_double("metrics_start_s", 0.0, Range{-1e6, 1e7});
        metrics_ = metrics::RunMetrics(t_gnss, t_start, cfg.get_double("attitude_trend_from_s", 500.0, Range{-1e6, 1e7}));
        decimation_ = static_cast<std::uint64_t>(cfg.get_int("decimation", 10, 1, 1'000'000));
        flush_rows_ = static_cast<std::size_t>(cfg.get_int("flush_rows", 600, 1, 1'000'000));
        compression_ = static_cast<int>(cfg.get_int("compression", 4, 0, 9));
        const std::string reference = cfg.get_string("reference", "truth");
        if (reference != "truth" && reference != "none")
            cfg.fail("reference", "'" + reference + "' is not one of truth, none");
        reference_ = reference == "truth";
        if (cfg.get_bool("alignment", false))  // in-flight alignment runs only: the time to align in metrics.yaml
            align_ = std::make_unique<framework::Input<msg::NavAlignment>>(*this, topics::kAlignment);
        if (cfg.get_bool("gnss_track", true))
            gnss_ = std::make_unique<framework::Input<msg::GnssSample>>(*this, topics::kGnss);
        dir_ = run.out_dir;
        truth_rows_.resize(flush_rows_ * io::run_series::kTruthColumns);
        est_rows_.resize(flush_rows_ * io::run_series::kEstimateColumns);
        err_rows_.resize(flush_rows_ * io::run_series::kErrorColumns);
        gnss_rows_.resize(flush_rows_ * io::run_series::kGnssColumns);
    }

    void step(const framework::StepContext& ctx) override {
        if (!truth_.available()) return;  // the essential producer is gone; nothing to compare
        const msg::Truth& t = truth_.get();
        if (!started_) start(t);
        const auto& v = t.v_n_mps();
        metrics_.add_ground_speed(ctx.t_s, ctx.dt_s, std::hypot(v[0], v[1]));
        const bool have_est = air_.available() && att_.available() && pos_.available();
        if (reference_) metrics_.note_estimates(ctx.t_s, ctx.dt_s, {air_.available(), att_.available(), pos_.available()});
        std::optional<metrics::NavErrors> err;
        if (have_est && reference_) {
            err = metrics::nav_errors(io::run_series::estimate_state(air_.get(), att_.get(), pos_.get()),
                                      io::run_series::truth_state(t), origin_.radii);
            metrics_.add_errors(ctx.t_s, ctx.dt_s, *err);
        }
        if (align_ && align_->available() && align_->get().aligned() && !t_aligned_s_)
            t_aligned_s_ = align_->get().t_aligned_s();
        last_k_ = ctx.k;
        ++steps_;
        if (dir_.empty()) return;
        if (gnss_ && gnss_->available() && gnss_->get().fix_valid() && gnss_count_ < flush_rows_)
            io::run_series::fill_gnss_row(&gnss_rows_[io::run_series::kGnssColumns * gnss_count_++], ctx.t_s,
                                          gnss_->get());
        if (ctx.k % decimation_ == 0) {
            double* truth_row = &truth_rows_[io::run_series::kTruthColumns * rows_];
            io::run_series::fill_truth_row(truth_row, ctx.t_s, t, origin_, metrics_.distance_since_gnss_m());
            // not a reference
            if (!reference_) std::fill(truth_row + 1, truth_row + io::run_series::kTruthColumns, kNoValue);
            const double h_m = reference_ || !pos_.available() ? t.h_m() : pos_.get().h_m();
            io::run_series::fill_estimate_row(&est_rows_[io::run_series::kEstimateColumns * rows_], ctx.t_s, air_.ptr(),
                                              att_.ptr(), pos_.ptr(), origin_, h_m);
            io::run_series::fill_error_row(&err_rows_[io::run_series::kErrorColumns * rows_], ctx.t_s,
                                           err ? &*err : nullptr);
            ++rows_;
        }
        if (rows_ == flush_rows_ || gnss_count_ == flush_rows_) flush(false);  // a WriteError ends the run
    }

    void finish(bool completed) override {
        if (finished_) return;
        finished_ = true;
        const bool complete = completed && started_ && last_k_ + 1 == run_.steps;
        if (dir_.empty() || !started_ || failed_) return;  // failed_: said once, when the write failed
        try {
            const SignalHold hold;
            flush(complete);
            if (reference_) {
                std::vector<H5File::MetricsRow> rows;
                for (const auto& info : metrics::kSignals) {
                    const auto& s = metrics_.stats(info.signal);
                    rows.push_back({std::string(info.key), s.count(), s.mean(), s.std(), s.smax(), s.last()});
                }
                file_->write_metrics("metrics", rows);
            }
            file_->set_attribute("complete", static_cast<std::int64_t>(complete ? 1 : 0));
            file_->close();
        } catch (const files::WriteError&) {
            throw;  // the run's cause (flush has left no file claiming a complete run)
        } catch (const std::exception& e) {
            spdlog::error("nav_recorder: {}", e.what());
        }
        spdlog::info("nav_recorder: {} run; {} -> {}", complete ? "complete" : "INCOMPLETE", summary(), dir_);
    }

private:
    static constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

    // The end-of-run line: the final horizontal error at t_end with the distance flown up to then, and the mean
    // attitude error; when an estimator stopped, both are labelled with the time of its last estimate.
    [[nodiscard]] std::string summary() const {
        if (!reference_) return "reference: none, no error metrics";
        const auto& hor = metrics_.stats(metrics::Signal::hor);
        const auto& rot = metrics_.stats(metrics::Signal::rot);
        const bool whole = metrics_.estimates_complete();
        std::string stopped;
        for (std::size_t i = 0; i < metrics::kEstimateCount; ++i)
            if (metrics_.estimate_stopped(static_cast<metrics::Estimate>(i)))
                stopped += fmt::format("{}{}", stopped.empty() ? "" : ", ", metrics::kEstimateKeys[i]);
        const std::string at =
            whole ? std::string("final")
                  : fmt::format("final at t = {:.2f} s (last step with every estimate; stopped: {})", metrics_.t_last_s(),
                                stopped);
        const std::string att = rot.count() > 0
                                    ? fmt::format("mean attitude error {:.3f} deg{}", math::rad2deg(rot.mean()),
                                                  whole ? "" : fmt::format(" over [0, {:.2f}] s", metrics_.t_last_s()))
                                    : std::string("no attitude error yet (metrics start at t = 0)");
        const double d_m = whole ? metrics_.distance_since_gnss_m() : metrics_.distance_at_t_last_m();
        std::string horizontal = "no horizontal figure (metrics start at t = 0)";
        if (hor.count() > 0 && d_m > 0.0)
            horizontal = fmt::format("{} horizontal error {:.1f} m ({:.2f} % of {:.0f} m {}since t_GNSS{})", at,
                                     hor.last(), metrics_.final_percent(metrics::Signal::hor), d_m,
                                     whole ? "" : "flown ", whole ? "" : " up to then");
        else if (hor.count() > 0)
            horizontal = fmt::format("{} horizontal error {:.1f} m (GNSS {})", at, hor.last(),
                                     whole ? "never lost" : "not lost by then");
        return fmt::format("{}{}, {}", whole ? "" : "ESTIMATES INCOMPLETE; ", horizontal, att);
    }

    void start(const msg::Truth& t) {
        started_ = true;
        // Said once, at the run's first step (configure also runs when a run is only checked).
        if (!reference_)
            spdlog::warn("nav_recorder: reference: none (no recorded Truth drives the physics): no error metrics, "
                         "only the estimates are recorded (docs/replay.md)");
        origin_.lat_rad = t.lat_rad();
        origin_.lon_rad = t.lon_rad();
        origin_.radii = earth::radii(t.lat_rad());
        if (dir_.empty()) return;
        fs::create_directories(dir_);
        std::error_code ec;
        fs::remove(fs::path(dir_) / "metrics.yaml", ec);  // a stale record of an earlier run must not survive
        file_ = std::make_unique<H5File>(fs::path(dir_) / "run.h5");
        tables_[0] = file_->add_table("truth", io::run_series::truth_columns(), flush_rows_, compression_);
        tables_[1] = file_->add_table("estimate", io::run_series::estimate_columns(), flush_rows_, compression_);
        tables_[2] = file_->add_table("error", io::run_series::error_columns(), flush_rows_, compression_);
        if (gnss_) tables_[3] = file_->add_table("gnss", io::run_series::gnss_columns(), flush_rows_, compression_);
        file_->set_attribute("format", std::string("gdnav-nav-record"));
        file_->set_attribute("format_version", kFormatVersion);
        file_->set_attribute("complete", static_cast<std::int64_t>(0));
        file_->set_attribute("seed", static_cast<std::int64_t>(run_.seed));
        file_->set_attribute("run_index", static_cast<std::int64_t>(run_.run_index));
        file_->set_attribute("dt_s", run_.dt_s);
        file_->set_attribute("t0_s", run_.t0_s);
        file_->set_attribute("decimation", static_cast<std::int64_t>(decimation_));
        file_->set_attribute("t_gnss_s", metrics_.t_gnss_s());
        file_->set_attribute("steps_planned", static_cast<std::int64_t>(run_.steps));
        file_->set_attribute("lat0_rad", origin_.lat_rad);
        file_->set_attribute("lon0_rad", origin_.lon_rad);
        if (!reference_) file_->set_attribute("reference", std::string("none"));
        file_->set_table_attribute(tables_[0], "description", "true state (Truth topic), SI units, NED");
        file_->set_table_attribute(tables_[1], "description", "navigation estimate (AirData/Attitude/PositionEstimate)");
        file_->set_table_attribute(tables_[2], "description", "estimate minus truth (docs/montecarlo.md)");
        file_->flush();
    }

    // Appends the buffered rows and rewrites metrics.yaml. A write the operating system refuses (files::WriteError)
    // leaves no file claiming a complete run: metrics.yaml is rewritten as incomplete, or removed when even that
    // fails, and run.h5 keeps complete = 0; the error goes on to the host, which ends the run with it.
    void flush(bool complete) {
        if (!file_) return;
        try {
            write_files(complete);
        } catch (const files::WriteError&) {
            failed_ = true;
            std::error_code ec;
            try {
                write_record(false);
            } catch (const files::WriteError&) {
                fs::remove(fs::path(dir_) / "metrics.yaml", ec);
            }
            throw;
        }
    }

    void write_files(bool complete) {
        const SignalHold hold;
        file_->append(tables_[0], truth_rows_.data(), rows_);
        file_->append(tables_[1], est_rows_.data(), rows_);
        file_->append(tables_[2], err_rows_.data(), rows_);
        if (gnss_) file_->append(tables_[3], gnss_rows_.data(), gnss_count_);
        rows_ = 0;
        gnss_count_ = 0;
        file_->set_attribute("steps_recorded", static_cast<std::int64_t>(steps_));
        file_->set_attribute("distance_since_gnss_m", reference_ ? metrics_.distance_since_gnss_m() : kNoValue);
        file_->flush();
        write_record(complete);
    }

    // metrics.yaml, whole or not at all (files::write_whole).
    void write_record(bool complete) const {
        const metrics::RunRecord r =
            reference_ ? metrics::make_run_record(metrics_, complete, run_.seed, run_.run_index, steps_)
                       : metrics::make_unreferenced_record(complete, run_.seed, run_.run_index, steps_, metrics_.t_gnss_s());
        files::write_whole(fs::path(dir_) / "metrics.yaml", metrics::to_yaml(r) + alignment_text());
    }

    // `alignment:` of metrics.yaml: when the navigation declared itself aligned (never: aligned false, no times).
    [[nodiscard]] std::string alignment_text() const {
        if (!align_) return "";
        std::ostringstream f;
        if (t_aligned_s_)
            f << "alignment: {aligned: true, t_aligned_s: " << *t_aligned_s_
              << ", time_to_align_s: " << *t_aligned_s_ - run_.t0_s << "}\n";
        else
            f << "alignment: {aligned: false}\n";
        return f.str();
    }

    framework::Input<msg::Truth> truth_{*this, topics::kTruth};
    framework::Input<msg::AirDataEstimate> air_{*this, topics::kAirData};
    framework::Input<msg::AttitudeEstimate> att_{*this, topics::kAttitude};
    framework::Input<msg::PositionEstimate> pos_{*this, topics::kPosition};
    std::unique_ptr<framework::Input<msg::GnssSample>> gnss_;
    std::unique_ptr<framework::Input<msg::NavAlignment>> align_;
    std::optional<double> t_aligned_s_;

    framework::RunInfo run_;
    metrics::RunMetrics metrics_;
    io::run_series::Origin origin_;
    std::string dir_;
    std::uint64_t decimation_{10};
    std::size_t flush_rows_{600};
    int compression_{4};
    std::unique_ptr<H5File> file_;
    std::array<int, 4> tables_{-1, -1, -1, -1};
    std::vector<double> truth_rows_, est_rows_, err_rows_, gnss_rows_;
    std::size_t rows_{0};
    std::size_t gnss_count_{0};
    std::uint64_t steps_{0};
    std::uint64_t last_k_{0};
    bool failed_{false};    // a write was refused (flush): nothing more is written
    bool reference_{true};  // Truth is the reference trajectory (false: `reference: none`, no errors)
    bool started_{false};
    bool finished_{false};
};

}  // namespace

void register_nav_recorder(framework::ComponentRegistry& reg) {
    reg.add("nav_recorder", "navigation errors, online metrics and HDF5 time series (run.h5, metrics.yaml)",
            framework::make_factory<NavRecorder>());
}

}  // namespace gdnav::nav_recorder
