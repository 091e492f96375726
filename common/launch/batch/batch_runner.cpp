#include "launch/batch/batch_runner.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>
#include <vector>

#include <spdlog/spdlog.h>

#include "dds/process/process_signals.hpp"
#include "framework/lockstep.hpp"
#include "framework/run_config.hpp"
#include "launch/children.hpp"
#include "files/write_error.hpp"
#include "launch/batch/batch_failures.hpp"
#include "launch/batch/batch_prepare.hpp"
#include "launch/batch/run_files.hpp"
#include "launch/member_process.hpp"
#include "framework/scenario_generator.hpp"
#include "metrics/run_record.hpp"

namespace gdnav::launch::batch {

namespace fs = std::filesystem;
using namespace gdnav::launch;

namespace {

struct Worker {
    std::uint64_t run{0};
    unsigned slot{0};  // of spec.jobs: with a first domain D, the run's domain is D + slot
    pid_t pid{0};
    double started_s{0.0};
    fs::path dir;
};

std::string read_tail(const fs::path& p, std::size_t bytes = 4096) {
    std::ifstream f(p, std::ios::binary);
    if (!f) return {};
    f.seekg(0, std::ios::end);
    const auto size = static_cast<std::size_t>(f.tellg());
    const std::size_t n = std::min(size, bytes);
    f.seekg(static_cast<std::streamoff>(size - n));
    std::string s(n, '\0');
    f.read(s.data(), static_cast<std::streamsize>(n));
    return s;
}

// Fraction of a running run done, from the last "step k/N" progress line of its log (0 when unknown).
double progress_of(const fs::path& log) {
    static const std::regex re(R"(step (\d+)/(\d+))");
    const std::string tail = read_tail(log);
    double frac = 0.0;
    for (std::sregex_iterator it(tail.begin(), tail.end(), re), end; it != end; ++it)
        frac = std::stod((*it)[1]) / std::max(1.0, std::stod((*it)[2]));
    return std::clamp(frac, 0.0, 1.0);
}

pid_t spawn_logged(const fs::path& exe, const std::vector<std::string>& args, const fs::path& log) {
    SpawnOptions o;
    o.log = log;
    o.log_truncate = true;
    return spawn(exe, args, o);
}

std::string hms(double s) {
    if (!std::isfinite(s) || s < 0) return "--";
    const long t = std::lround(s);
    char b[32];
    if (t >= 3600)
        std::snprintf(b, sizeof(b), "%ldh%02ldm", t / 3600, (t / 60) % 60);
    else
        std::snprintf(b, sizeof(b), "%ldm%02lds", t / 60, t % 60);
    return b;
}

// The supervision loop of one shard: starts up to `jobs` runs, reaps them, prints progress, stops on Ctrl-C.
class ShardRun {
public:
    ShardRun(const BatchSpec& spec, const PreparedBatch& p, std::vector<std::uint64_t> todo, std::size_t skipped)
        : spec_(spec), p_(p), todo_(std::move(todo)), skipped_(skipped) {}

    void run() {
        dds::install_stop_signal_handlers();
        exe_ = fs::read_symlink("/proc/self/exe");
        tty_ = isatty(STDERR_FILENO) != 0;
        t0_ = framework::steady_now_s();
        while ((next_ < todo_.size() && !interrupted_ && !write_failed_) || !workers_.empty()) {
            if (dds::stop_requested() && !interrupted_) interrupt();
            start_workers();
            if (reap_one()) continue;
            if (interrupted_ && framework::steady_now_s() > kill_at_s_)
                for (const auto& w : workers_) kill(w.pid, SIGKILL);  // the launchers had 10 s to stop their processes
            print_progress(false);
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        }
        print_progress(true);
    }

    int finish(const std::string& which) const {
        if (!failures_.empty()) {
            spdlog::error("montecarlo: {} run(s) failed:", failures_.size());
            for (const auto& f : failures_)
                spdlog::error("  run {} ({}): exit code {}: {}", f.run, (p_.dir / "runs" / run_dir_name(f.run)).string(),
                              f.exit_code, f.cause);
            spdlog::error("montecarlo: their last log lines are in {}; run the same command again to rerun them",
                          (p_.dir / "failures.yaml").string());
        }
        if (interrupted_) {
            spdlog::warn(
                "montecarlo: interrupted after {} new runs; run the same command again to complete the missing ones",
                done_now_);
            return framework::kExitInterrupted;
        }
        if (write_failed_) {
            spdlog::error("montecarlo: stopped: a run could not write its files; {} complete runs ({} new), {} not "
                          "started; free space and run the same command again to complete the batch",
                          skipped_ + done_now_, done_now_, todo_.size() - next_);
            return framework::kExitWriteFailed;
        }
        spdlog::info("montecarlo:{} {} complete runs ({} new, {} skipped), {} failed, {:.1f} s", which,
                     skipped_ + done_now_, done_now_, skipped_, failures_.size(), framework::steady_now_s() - t0_);
        return failures_.empty() ? 0 : 1;
    }

private:
    void interrupt() {
        interrupted_ = true;
        if (tty_) std::fprintf(stderr, "\n");
        spdlog::warn("montecarlo: interrupted; stopping {} running runs", workers_.size());
        for (const auto& w : workers_) kill(w.pid, SIGTERM);
        kill_at_s_ = framework::steady_now_s() + 10.0;
    }

    // The run's failure record (failure.yaml); on a full disk, where even that cannot be written, the cause as far as
    // the exit code tells it.
    RunFailure failure_of(const Worker& w, int code) const {
        RunFailure f;
        try {
            f = record_run_failure(w.dir, w.run, code);
        } catch (const std::exception&) {
            f.run = w.run;
            f.exit_code = code;
            f.log_tail = last_lines(w.dir / "log.txt", 1);
            f.cause = f.log_tail.empty() ? "(no output in log.txt)" : f.log_tail.back();
        }
        if (code == framework::kExitWriteFailed && f.cause.find("cannot write") == std::string::npos)
            f.cause = "an output file could not be written (exit code 6; " + f.cause + ")";
        return f;
    }

    void start_workers() {
        while (!interrupted_ && !write_failed_ && next_ < todo_.size() && workers_.size() < spec_.jobs) {
            Worker w;
            w.run = todo_[next_++];
            w.slot = free_slot();
            w.dir = p_.dir / "runs" / run_dir_name(w.run);
            std::error_code ec;
            fs::remove_all(w.dir, ec);  // stale files of an interrupted attempt
            fs::create_directories(w.dir);
            write_drawn_scenario(p_, w.run, w.dir);
            std::vector<std::string> args{"run",         "--scenario", (p_.dir / "scenario.yaml").string(),
                                          "--seed",      std::to_string(p_.seed),
                                          "--run",       std::to_string(w.run),
                                          "--layout",    spec_.layout,
                                          "--out",       w.dir.string(),
                                          "--log-level", spec_.log_level};
            // Without a first domain each run takes a DDS domain no other run of this host uses (launch/domain_lock.hpp).
            if (p_.first_domain >= 0)
                args.insert(args.end(), {"--domain", std::to_string(p_.first_domain + static_cast<int>(w.slot))});
            w.pid = spawn_logged(exe_, args, w.dir / "log.txt");
            w.started_s = framework::steady_now_s();
            workers_.push_back(w);
        }
    }

    // The lowest parallel slot no running worker holds.
    unsigned free_slot() const {
        for (unsigned s = 0;; ++s)
            if (std::none_of(workers_.begin(), workers_.end(), [s](const Worker& w) { return w.slot == s; })) return s;
    }

    // Reaps one ended child, if any; true when a child was reaped.
    bool reap_one() {
        int st = 0;
        const pid_t pid = waitpid(-1, &st, WNOHANG);
        if (pid <= 0) return false;
        auto it = std::find_if(workers_.begin(), workers_.end(), [pid](const Worker& w) { return w.pid == pid; });
        if (it != workers_.end()) {
            int code = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
            bool ok = code == 0 && metrics::run_record_complete(it->dir / "metrics.yaml");
            if (ok) {
                try {
                    write_run_files(it->dir);
                } catch (const files::WriteError& e) {
                    spdlog::error("montecarlo: run {}: {}", it->run, e.what());
                    ok = false;
                    code = framework::kExitWriteFailed;
                }
            }
            if (ok) {
                ++done_now_;
            } else if (!interrupted_) {
                failures_.push_back(failure_of(*it, code == 0 ? 1 : code));
                if (code == framework::kExitWriteFailed && !write_failed_) {
                    // Every further run would meet the same full disk: none is started; the batch resumes later.
                    write_failed_ = true;
                    spdlog::error("montecarlo: run {} could not write its files ({}); no new run is started. Free "
                                  "space in {} and run the same command again to go on",
                                  it->run, failures_.back().cause, p_.dir.string());
                }
            }
            workers_.erase(it);
            print_progress(false);
        }
        return true;
    }

    void print_progress(bool final_line) {
        const double now = framework::steady_now_s();
        if (!final_line && now - last_print_ < (tty_ ? 0.5 : 15.0)) return;
        last_print_ = now;
        double partial = 0.0;
        for (const auto& w : workers_) partial += progress_of(w.dir / "log.txt");
        const double elapsed = now - t0_;
        const double sim_done = (static_cast<double>(done_now_ + failures_.size()) + partial) * p_.sim_per_run_s;
        const double speed = elapsed > 0 ? sim_done / elapsed : 0.0;
        const double remaining = static_cast<double>(todo_.size()) * p_.sim_per_run_s - sim_done;
        char line[256];
        std::snprintf(line, sizeof(line),
                      "montecarlo: %zu/%llu runs done, %zu failed, %zu running | %s elapsed, ETA %s | %.0fx real time",
                      skipped_ + done_now_, static_cast<unsigned long long>(p_.mine.size()), failures_.size(),
                      workers_.size(), hms(elapsed).c_str(), speed > 0 ? hms(remaining / speed).c_str() : "--", speed);
        if (tty_)
            std::fprintf(stderr, "\r%s\033[K%s", line, final_line ? "\n" : "");
        else
            std::fprintf(stderr, "%s\n", line);
        std::fflush(stderr);
    }

    const BatchSpec& spec_;
    const PreparedBatch& p_;
    const std::vector<std::uint64_t> todo_;
    const std::size_t skipped_;
    std::vector<Worker> workers_;
    std::vector<RunFailure> failures_;
    fs::path exe_;
    bool tty_{false};
    std::size_t next_{0}, done_now_{0};
    double t0_{0.0}, last_print_{0.0}, kill_at_s_{0.0};
    bool interrupted_{false};
    bool write_failed_{false};  // a run could not write its files: no new run is started
};

}  // namespace

int run_batch_shard(const BatchSpec& spec, const framework::ComponentRegistry& reg, const Shard& shard) {
    const PreparedBatch p = prepare_batch(spec, reg, shard);
    std::size_t skipped = 0;
    std::vector<std::uint64_t> todo = runs_to_do(p, skipped);
    const std::string which =
        shard.whole() ? "" : " shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count) + ":";
    spdlog::info("montecarlo:{} {} runs of {} (seed {}, runs {}..{}, layout {}, {} jobs) -> {}; {} already complete",
                 which, p.mine.size(), spec.file.filename().string(), p.seed, spec.first, spec.first + spec.runs - 1,
                 spec.layout, spec.jobs, p.dir.string(), skipped);
    if (p.first_domain >= 0 && spec.layout != "direct")
        spdlog::info("montecarlo: DDS domains {}..{} (one per parallel slot)", p.first_domain,
                     p.first_domain + static_cast<int>(spec.jobs) - 1);
    ShardRun r(spec, p, std::move(todo), skipped);
    r.run();
    write_failures_summary(p.dir);
    return r.finish(which);
}

}  // namespace gdnav::launch::batch
