// gdnav montecarlo: runs N runs of a scenario as parallel `gdnav run` child processes, resumably, with a live
// progress line, then aggregates them (commands_report). Batch directory:
//   DIR/scenario.yaml     the scenario with every override applied (each run: gdnav run --scenario DIR/scenario.yaml
//                         --seed S --run i --layout L --out DIR/runs/run_000i)
//   DIR/batch.yaml        how the batch was started
//   DIR/runs/run_NNNN/    each run's output (run.h5, metrics.yaml, run.yaml, log.txt)
//   DIR/report/           tables.md, aggregate.yaml, runs.csv, figures
// With --shard I/N only the I-th interleaved slice runs (batch_dir.hpp) and there is no report; --mpi spreads the
// slices over MPI ranks (montecarlo_mpi.cpp).
#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <regex>
#include <sstream>
#include <thread>

#include <spdlog/spdlog.h>

#include "commands.hpp"
#include "commands_report.hpp"
#include "commands_scenario.hpp"
#include "montecarlo.hpp"
#include "metrics/run_record.hpp"
#include "framework/lockstep.hpp"
#include "dds/process/process_signals.hpp"
#include "framework/run_config.hpp"

namespace gdnav::app {

namespace fs = std::filesystem;
using namespace gdnav::runtime;

namespace {

struct Worker {
    std::uint64_t run{0};
    pid_t pid{0};
    int slot{0};
    double started_s{0.0};
    fs::path dir;
};

struct Failure {
    std::uint64_t run;
    int code;
    std::string last_line;
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

std::string last_line(const fs::path& log) {
    std::istringstream in(read_tail(log));
    std::string line, last;
    while (std::getline(in, line))
        if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
    return last;
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
    std::vector<std::string> all{exe.string()};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& s : all) argv.push_back(s.data());
    argv.push_back(nullptr);
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        prctl(PR_SET_PDEATHSIG, SIGTERM);
        if (getppid() != parent) _exit(1);
        const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            dup2(fd, STDOUT_FILENO);
            dup2(fd, STDERR_FILENO);
            close(fd);
        }
        execv(exe.c_str(), argv.data());
        _exit(127);
    }
    return pid;
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

}  // namespace

int run_batch_shard(const McArgs& a, const CliContext& ctx, const Shard& shard) {
    ScenarioDocument s = load_scenario_document(a.scenario, a.o);
    if (a.seed_given || !s.doc["run"]["seed"]) s.doc["run"]["seed"] = a.seed;
    if (a.steps > 0) {
        s.doc["run"].remove("duration_s");
        s.doc["run"]["steps"] = a.steps;
    }
    s.doc["run"].remove("run_index");
    s.doc["run"].remove("out_dir");
    s.doc["run"].remove("domain_id");
    const std::string text = document_text(s.doc);
    // Validate the whole configuration once (run `first`) before starting anything.
    RunOverrides ro;
    ro.run_index = a.first;
    const RunConfig rc0 = RunConfig::parse(text, s.file.string(), ro);
    (void)rc0.build(ctx.registry);
    const std::uint64_t seed = rc0.info.seed;
    const double sim_per_run_s = static_cast<double>(rc0.info.steps) * rc0.info.dt_s;

    const fs::path dir = fs::absolute(a.out);
    prepare_batch_dir(dir, text);
    const std::string generator =
        s.doc["generator"] && s.doc["generator"]["name"] ? s.doc["generator"]["name"].Scalar() : "";
    {
        // The same text from every shard of a batch (they may share DIR); a whole batch records its jobs.
        std::ostringstream b;
        b << "# gdnav montecarlo batch (the latest invocation)\nscenario: " << a.scenario << "\nfile: " << s.file.string()
          << "\ngenerator: " << (generator.empty() ? "none" : generator) << "\nseed: " << seed << "\nfirst: " << a.first
          << "\nruns: " << a.runs << "\nlayout: " << a.layout << "\n";
        if (shard.whole())
            b << "jobs: " << a.jobs << "\n";
        else
            b << "shards: " << shard.count << "\n";
        write_file_atomic(dir / "batch.yaml", b.str());
    }
    const std::vector<std::uint64_t> mine = shard_runs(a.first, a.runs, shard);
    if (!shard.whole()) write_shard_record(dir, shard, a.jobs, mine.size());

    std::vector<std::uint64_t> todo;
    std::size_t skipped = 0;
    for (const std::uint64_t i : mine) {
        const fs::path m = dir / "runs" / run_dir_name(i) / "metrics.yaml";
        bool done = false;
        if (metrics::run_record_complete(m)) {
            const auto r = metrics::read_run_record(m);
            done = r.seed == seed && r.run_index == i;
        }
        if (done)
            ++skipped;
        else
            todo.push_back(i);
    }
    const std::string which =
        shard.whole() ? "" : " shard " + std::to_string(shard.index) + "/" + std::to_string(shard.count) + ":";
    spdlog::info("montecarlo:{} {} runs of {} (seed {}, runs {}..{}, layout {}, {} jobs) -> {}; {} already complete",
                 which, mine.size(), s.file.filename().string(), seed, a.first, a.first + a.runs - 1, a.layout, a.jobs,
                 dir.string(), skipped);

    install_stop_signal_handlers();
    const fs::path exe = fs::read_symlink("/proc/self/exe");
    const bool tty = isatty(STDERR_FILENO) != 0;
    const int domain_base = static_cast<int>(getpid() % 200);
    std::vector<Worker> workers;
    std::vector<bool> slot_busy(a.jobs, false);
    std::vector<Failure> failures;
    std::size_t next = 0, done_now = 0;
    const double t0 = steady_now_s();
    double last_print = 0.0;
    bool interrupted = false;
    double kill_at_s = 0.0;

    auto print_progress = [&](bool final_line) {
        const double now = steady_now_s();
        if (!final_line && now - last_print < (tty ? 0.5 : 15.0)) return;
        last_print = now;
        double partial = 0.0;
        for (const auto& w : workers) partial += progress_of(w.dir / "log.txt");
        const double elapsed = now - t0;
        const double sim_done = (static_cast<double>(done_now + failures.size()) + partial) * sim_per_run_s;
        const double speed = elapsed > 0 ? sim_done / elapsed : 0.0;
        const double remaining = static_cast<double>(todo.size()) * sim_per_run_s - sim_done;
        char line[256];
        std::snprintf(line, sizeof(line), "montecarlo: %zu/%llu runs done, %zu failed, %zu running | %s elapsed, ETA %s | %.0fx real time",
                      skipped + done_now, static_cast<unsigned long long>(mine.size()), failures.size(), workers.size(),
                      hms(elapsed).c_str(), speed > 0 ? hms(remaining / speed).c_str() : "--", speed);
        if (tty)
            std::fprintf(stderr, "\r%s\033[K%s", line, final_line ? "\n" : "");
        else
            std::fprintf(stderr, "%s\n", line);
        std::fflush(stderr);
    };

    while ((next < todo.size() && !interrupted) || !workers.empty()) {
        if (stop_requested() && !interrupted) {
            interrupted = true;
            if (tty) std::fprintf(stderr, "\n");
            spdlog::warn("montecarlo: interrupted; stopping {} running runs", workers.size());
            for (const auto& w : workers) kill(w.pid, SIGTERM);
            kill_at_s = steady_now_s() + 10.0;
        }
        while (!interrupted && next < todo.size() && workers.size() < a.jobs) {
            Worker w;
            w.run = todo[next++];
            w.slot = static_cast<int>(std::find(slot_busy.begin(), slot_busy.end(), false) - slot_busy.begin());
            slot_busy[static_cast<std::size_t>(w.slot)] = true;
            w.dir = dir / "runs" / run_dir_name(w.run);
            std::error_code ec;
            fs::remove_all(w.dir, ec);  // stale files of an interrupted attempt
            fs::create_directories(w.dir);
            const int domain = 20 + (domain_base + w.slot) % 200;
            std::vector<std::string> args{"run",           "--scenario", (dir / "scenario.yaml").string(),
                                          "--seed",        std::to_string(seed),
                                          "--run",         std::to_string(w.run),
                                          "--layout",      a.layout,
                                          "--out",         w.dir.string(),
                                          "--domain",      std::to_string(domain),
                                          "--log-level",   ctx.log_level};
            w.pid = spawn_logged(exe, args, w.dir / "log.txt");
            w.started_s = steady_now_s();
            workers.push_back(w);
        }
        int st = 0;
        const pid_t pid = waitpid(-1, &st, WNOHANG);
        if (pid > 0) {
            auto it = std::find_if(workers.begin(), workers.end(), [pid](const Worker& w) { return w.pid == pid; });
            if (it != workers.end()) {
                const int code = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
                const bool ok = code == 0 && metrics::run_record_complete(it->dir / "metrics.yaml");
                if (ok) {
                    ++done_now;
                } else if (!interrupted) {
                    failures.push_back({it->run, code == 0 ? 1 : code, last_line(it->dir / "log.txt")});
                }
                slot_busy[static_cast<std::size_t>(it->slot)] = false;
                workers.erase(it);
                print_progress(false);
            }
            continue;
        }
        if (interrupted && steady_now_s() > kill_at_s)
            for (const auto& w : workers) kill(w.pid, SIGKILL);  // the launchers had 10 s to stop their processes
        print_progress(false);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    print_progress(true);

    if (!failures.empty()) {
        spdlog::error("montecarlo: {} run(s) failed:", failures.size());
        for (const auto& f : failures)
            spdlog::error("  run {} ({}): exit code {}: {}", f.run, (dir / "runs" / run_dir_name(f.run)).string(), f.code,
                          f.last_line);
    }
    if (interrupted) {
        spdlog::warn("montecarlo: interrupted after {} new runs; run the same command again to complete the missing ones",
                     done_now);
        return kExitInterrupted;
    }
    spdlog::info("montecarlo:{} {} complete runs ({} new, {} skipped), {} failed, {:.1f} s", which, skipped + done_now,
                 done_now, skipped, failures.size(), steady_now_s() - t0);
    return failures.empty() ? 0 : 1;
}

int run_montecarlo(const McArgs& a, const CliContext& ctx) {
    if (a.mpi) {
#ifdef GDNAV_HAVE_MPI
        if (!a.shard.empty()) throw config::ConfigError("montecarlo: --mpi and --shard exclude each other");
        return run_montecarlo_mpi(a, ctx);
#else
        throw config::ConfigError("montecarlo: --mpi: this gdnav was built without MPI (install libopenmpi-dev and "
                                  "rebuild, see docs/montecarlo.md)");
#endif
    }
    const Shard shard = a.shard.empty() ? Shard{} : parse_shard(a.shard);
    int code = run_batch_shard(a, ctx, shard);
    if (code == kExitInterrupted) return code;
    if (!shard.whole()) {
        spdlog::info("montecarlo: shard {}/{} done; aggregate the shards with: gdnav report DIR [DIR ...]", shard.index,
                     shard.count);
    } else if (!a.no_report) {
        ReportOptions ro;
        ro.figures = !a.no_figures;
        const int rc = write_batch_report({fs::absolute(a.out)}, ro);
        if (rc != 0) code = code ? code : rc;
    }
    return code;
}

CLI::App* add_montecarlo_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    auto a = std::make_shared<McArgs>();
    auto* sub = app.add_subcommand("montecarlo", "run a Monte Carlo batch (parallel, resumable) and aggregate it");
    sub->add_option("--shard", a->shard, "run only shard I of N (I/N, 1-based: runs first+k with k mod N = I-1)");
    sub->add_flag("--mpi", a->mpi, "under mpirun: the ranks share the runs, rank 0 writes the report");
    sub->add_option("--scenario", a->scenario, "1, 2 (paper scenarios), a scenario name or a YAML file");
    sub->add_option("--runs", a->runs, "number of runs")->check(CLI::Range(1, 1000000));
    sub->add_option("--first", a->first, "index of the first run");
    sub->add_option("--seed", a->seed, "master seed (default: the scenario file's)");
    sub->add_option("--jobs,-j", a->jobs, "runs in parallel")->check(CLI::Range(1, 256));
    sub->add_option("--layout", a->layout, "direct | composed | distributed")
        ->check(CLI::IsMember({"direct", "composed", "distributed"}));
    sub->add_option("--out", a->out, "batch directory")->required();
    sub->add_option("--steps", a->steps, "override the number of steps of every run");
    sub->add_option("--set", a->o.sets, "override a key: path.to.key=value (YAML value; ~ removes)");
    sub->add_option("--grade", a->o.grades, "sensor grade for every group (NAME) or one group (GROUP=NAME)");
    sub->add_option("--variant", a->o.variants, "navigation variant NAME (nav_att, nav_pos) or COMPONENT=NAME");
    sub->add_flag("--no-report", a->no_report, "do not aggregate at the end");
    sub->add_flag("--no-figures", a->no_figures, "aggregate tables only");
    run = [a, sub, &ctx]() {
        setup_logging("gdnav", ctx.log_level);
        a->seed_given = sub->count("--seed") > 0;
        return run_montecarlo(*a, ctx);
    };
    return sub;
}

}  // namespace gdnav::app
