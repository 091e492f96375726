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
#include "launch/batch/batch_failures.hpp"
#include "launch/member_process.hpp"
#include "framework/scenario_generator.hpp"
#include "metrics/run_record.hpp"

namespace gdnav::app {

namespace fs = std::filesystem;
using namespace gdnav::runtime;

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

// The scenario every run of the batch reads: the spec's seed and steps applied, the per-run keys removed.
std::string batch_scenario_text(const BatchSpec& spec) {
    YAML::Node doc = YAML::Clone(spec.doc);
    if (spec.seed_given || !doc["run"]["seed"]) doc["run"]["seed"] = spec.seed;
    if (spec.steps > 0) {
        doc["run"].remove("duration_s");
        doc["run"]["steps"] = spec.steps;
    }
    doc["run"].remove("run_index");
    doc["run"].remove("out_dir");
    doc["run"].remove("domain_id");
    YAML::Emitter em;
    em.SetDoublePrecision(17);
    em << doc;
    return std::string(em.c_str()) + "\n";
}

// Writes DIR/scenario.yaml, or checks that an existing one (a batch being resumed) is the same.
void prepare_batch_dir(const fs::path& dir, const std::string& text) {
    fs::create_directories(dir / "runs");
    const fs::path file = dir / "scenario.yaml";
    const std::string content = "# Scenario of this batch (overrides applied); written by gdnav montecarlo\n" + text;
    if (fs::exists(file)) {
        if (read_text(file) != content)
            throw config::ConfigError("montecarlo: " + dir.string() +
                                      " holds a batch of a different scenario or settings (scenario.yaml differs); "
                                      "use another --out or remove the folder");
        return;
    }
    write_file_atomic(file, content);  // shards sharing DIR may write it at the same time (the same text)
}

// DIR/batch.yaml: the same text from every shard of a batch (they may share DIR); a whole batch records its jobs.
void write_batch_record(const BatchSpec& spec, const fs::path& dir, std::uint64_t seed, const Shard& shard) {
    const std::string generator =
        spec.doc["generator"] && spec.doc["generator"]["name"] ? spec.doc["generator"]["name"].Scalar() : "";
    std::ostringstream b;
    b << "# gdnav montecarlo batch (the latest invocation)\nscenario: " << spec.scenario
      << "\nfile: " << spec.file.string() << "\ngenerator: " << (generator.empty() ? "none" : generator)
      << "\nseed: " << seed << "\nfirst: " << spec.first << "\nruns: " << spec.runs << "\nlayout: " << spec.layout
      << "\n";
    if (shard.whole())
        b << "jobs: " << spec.jobs << "\n";
    else
        b << "shards: " << shard.count << "\n";
    write_file_atomic(dir / "batch.yaml", b.str());
}

// The batch as validated and recorded in its directory.
struct PreparedBatch {
    fs::path dir;
    std::uint64_t seed{0};
    double sim_per_run_s{0.0};
    std::vector<std::uint64_t> mine;  // this shard's run indices
    int first_domain{-1};             // >= 0: slot k runs on DDS domain first_domain + k
    YAML::Node doc;                   // DIR/scenario.yaml's document
};

// The domain of slot 0: --domain, else the document's run.domain_id (a batch's runs cannot share one domain, so a
// given domain is the first of `jobs` consecutive ones), else none (each run takes a free one).
int first_domain(const BatchSpec& spec) {
    int d = spec.domain;
    std::string key = "--domain";
    if (d < 0 && spec.doc["run"] && spec.doc["run"]["domain_id"]) {
        key = "run.domain_id";
        try {
            d = spec.doc["run"]["domain_id"].as<int>();
        } catch (const YAML::Exception&) {
            d = -1;
        }
        if (d < 0 || d > 232)
            throw config::ConfigError("config error: " + spec.file.string() + ": run.domain_id: must be an integer in [0, 232]");
    }
    if (d >= 0 && d + static_cast<int>(spec.jobs) - 1 > 232)
        throw config::ConfigError("config error: " + key + " " + std::to_string(d) + " with --jobs " +
                                  std::to_string(spec.jobs) + ": the slots need domains " + std::to_string(d) + ".." +
                                  std::to_string(d + static_cast<int>(spec.jobs) - 1) + ", above 232 (the highest DDS domain)");
    return d;
}

// RUN_DIR/drawn_scenario.yaml: what the scenario's generator drew for this run (framework/scenario_generator.hpp),
// so that `gdnav compare` can tell by its SHA-256 whether two batches flew the same missions. Nothing when the
// scenario has no generator. Written beside the run's outputs: no recorded topic or metric changes.
void write_drawn_scenario(const PreparedBatch& p, std::uint64_t run, const fs::path& run_dir) {
    const YAML::Node drawn = drawn_scenario(p.doc, p.seed, run, (p.dir / "scenario.yaml").string());
    if (!drawn || drawn.IsNull()) return;
    YAML::Emitter em;
    em.SetDoublePrecision(17);
    em << drawn;
    write_file_atomic(run_dir / "drawn_scenario.yaml",
                      "# Scenario drawn for this run by its generator (components reduced to their type); written by "
                      "gdnav montecarlo\n" + std::string(em.c_str()) + "\n");
}

PreparedBatch prepare_batch(const BatchSpec& spec, const ComponentRegistry& reg, const Shard& shard) {
    const std::string text = batch_scenario_text(spec);
    // Validate the whole configuration once (run `first`) before starting anything.
    RunOverrides ro;
    ro.run_index = spec.first;
    const RunConfig rc0 = RunConfig::parse(text, spec.file.string(), ro);
    (void)rc0.build(reg);
    check_started_members(rc0, spec.layout);
    {  // every member's command is found (placeholders of a run in the current directory)
        RunConfig probe = rc0;
        probe.out_dir = ".";
        (void)resolve_member_processes(probe);
    }
    PreparedBatch p;
    p.first_domain = first_domain(spec);
    p.seed = rc0.info.seed;
    p.sim_per_run_s = static_cast<double>(rc0.info.steps) * rc0.info.dt_s;
    p.dir = fs::absolute(spec.out);
    p.doc = YAML::Load(text);
    prepare_batch_dir(p.dir, text);
    write_batch_record(spec, p.dir, p.seed, shard);
    p.mine = shard_runs(spec.first, spec.runs, shard);
    if (!shard.whole()) write_shard_record(p.dir, shard, spec.jobs, p.mine.size());
    return p;
}

// Runs of the shard still to do: those without a complete metrics.yaml of this seed and index.
std::vector<std::uint64_t> runs_to_do(const PreparedBatch& p, std::size_t& skipped) {
    std::vector<std::uint64_t> todo;
    skipped = 0;
    for (const std::uint64_t i : p.mine) {
        const fs::path m = p.dir / "runs" / run_dir_name(i) / "metrics.yaml";
        bool done = false;
        if (metrics::run_record_complete(m)) {
            const auto r = metrics::read_run_record(m);
            done = r.seed == p.seed && r.run_index == i;
        }
        if (done)
            ++skipped;
        else
            todo.push_back(i);
    }
    return todo;
}

// The supervision loop of one shard: starts up to `jobs` runs, reaps them, prints progress, stops on Ctrl-C.
class ShardRun {
public:
    ShardRun(const BatchSpec& spec, const PreparedBatch& p, std::vector<std::uint64_t> todo, std::size_t skipped)
        : spec_(spec), p_(p), todo_(std::move(todo)), skipped_(skipped) {}

    void run() {
        install_stop_signal_handlers();
        exe_ = fs::read_symlink("/proc/self/exe");
        tty_ = isatty(STDERR_FILENO) != 0;
        t0_ = steady_now_s();
        while ((next_ < todo_.size() && !interrupted_) || !workers_.empty()) {
            if (stop_requested() && !interrupted_) interrupt();
            start_workers();
            if (reap_one()) continue;
            if (interrupted_ && steady_now_s() > kill_at_s_)
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
            return kExitInterrupted;
        }
        spdlog::info("montecarlo:{} {} complete runs ({} new, {} skipped), {} failed, {:.1f} s", which,
                     skipped_ + done_now_, done_now_, skipped_, failures_.size(), steady_now_s() - t0_);
        return failures_.empty() ? 0 : 1;
    }

private:
    void interrupt() {
        interrupted_ = true;
        if (tty_) std::fprintf(stderr, "\n");
        spdlog::warn("montecarlo: interrupted; stopping {} running runs", workers_.size());
        for (const auto& w : workers_) kill(w.pid, SIGTERM);
        kill_at_s_ = steady_now_s() + 10.0;
    }

    void start_workers() {
        while (!interrupted_ && next_ < todo_.size() && workers_.size() < spec_.jobs) {
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
            w.started_s = steady_now_s();
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
            const int code = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
            const bool ok = code == 0 && metrics::run_record_complete(it->dir / "metrics.yaml");
            if (ok) {
                ++done_now_;
            } else if (!interrupted_) {
                failures_.push_back(record_run_failure(it->dir, it->run, code == 0 ? 1 : code));
            }
            workers_.erase(it);
            print_progress(false);
        }
        return true;
    }

    void print_progress(bool final_line) {
        const double now = steady_now_s();
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
};

}  // namespace

int run_batch_shard(const BatchSpec& spec, const ComponentRegistry& reg, const Shard& shard) {
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

}  // namespace gdnav::app
