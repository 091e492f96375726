// gdnav report DIR [DIR2 ...]: the paper's aggregated tables and figures of one or more batch directories.
#include "commands_report.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <memory>

#include <spdlog/spdlog.h>

#include "commands.hpp"
#include "config/config.hpp"
#include "metrics/report_tables.hpp"
#include "runtime/run_config.hpp"

namespace gdnav::app {

namespace fs = std::filesystem;

namespace {

// Label of a batch in the tables: "#1" / "#2" for the paper scenarios, else the scenario name.
std::string batch_label(const fs::path& dir) {
    std::string label = dir.filename().string();
    try {
        const config::Config b = config::Config::load(dir / "batch.yaml");
        const std::string gen = b.get_string("generator", "");
        if (gen == "paper_scenario1") return "#1";
        if (gen == "paper_scenario2") return "#2";
        label = b.get_string("scenario", label);
    } catch (const std::exception&) {
    }
    return label;
}

std::vector<metrics::RunRecord> complete_runs(const fs::path& dir) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir / "runs", ec))
        if (e.is_directory() && fs::exists(e.path() / "metrics.yaml")) files.push_back(e.path() / "metrics.yaml");
    std::sort(files.begin(), files.end());
    std::vector<metrics::RunRecord> runs;
    for (const auto& f : files) {
        try {
            metrics::RunRecord r = metrics::read_run_record(f);
            if (r.complete) runs.push_back(std::move(r));
        } catch (const config::ConfigError& e) {
            spdlog::warn("skipping {}: {}", f.string(), e.what());
        }
    }
    std::sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.run_index < b.run_index; });
    return runs;
}

void write_text(const fs::path& p, const std::string& text) {
    std::ofstream f(p, std::ios::trunc);
    f << text;
    if (!f) throw std::runtime_error("cannot write " + p.string());
}

int run_figures(const fs::path& batch, const fs::path& out) {
    const char* py_env = std::getenv("GDNAV_PYTHON");
    const char* script_env = std::getenv("GDNAV_REPORT_SCRIPT");
    const std::string py = py_env && *py_env ? py_env : "/usr/bin/python3";
    const fs::path script = script_env && *script_env ? fs::path(script_env)
                                                      : runtime::config_dir().parent_path() / "tools/report/report.py";
    if (!fs::exists(script)) {
        spdlog::error("figures: {} not found (set GDNAV_REPORT_SCRIPT)", script.string());
        return 1;
    }
    std::vector<std::string> args{py, script.string(), batch.string(), "--out", out.string()};
    std::vector<char*> argv;
    for (auto& s : args) argv.push_back(s.data());
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid < 0) return 1;
    if (pid == 0) {
        execv(py.c_str(), argv.data());
        _exit(127);
    }
    int st = 0;
    while (waitpid(pid, &st, 0) < 0) {
    }
    const int code = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
    if (code != 0) spdlog::error("figures: {} {} failed with code {}", py, script.string(), code);
    return code;
}

}  // namespace

int write_batch_report(const std::vector<fs::path>& dirs, const ReportOptions& o, std::vector<std::size_t>* counts) {
    if (dirs.empty()) throw config::ConfigError("report: no batch directory given");
    const fs::path out = o.out.empty() ? dirs.front() / "report" : o.out;
    fs::create_directories(out);
    std::vector<metrics::LabelledBatch> batches;
    std::string preamble = "# Aggregated navigation system error (NSE)\n\n";
    for (const auto& d : dirs) {
        if (!fs::is_directory(d / "runs")) throw config::ConfigError("report: " + d.string() + " holds no runs/ folder");
        metrics::LabelledBatch b;
        b.label = batch_label(d);
        b.runs = complete_runs(d);
        b.aggregate = metrics::aggregate_runs(b.runs);
        if (counts) counts->push_back(b.runs.size());
        preamble += "- " + b.label + ": " + std::to_string(b.runs.size()) + " complete runs in " + d.string() + "\n";
        if (b.runs.empty()) spdlog::warn("report: no complete run in {}", d.string());
        batches.push_back(std::move(b));
    }
    preamble += "\nAggregated metrics: mean, population std and max (largest |value|, sign kept; for per-run maxima "
                "mean and std of |max|) across runs of each per-run metric (t in [0, t_end]). Final: value at t_end. "
                "Distance: true ground distance since t_GNSS; % = 100 · error / distance per run, then aggregated.\n";
    write_text(out / "tables.md", metrics::paper_tables_markdown(batches, preamble));
    if (batches.size() == 1) {
        write_text(out / "aggregate.yaml", metrics::to_yaml(batches.front().aggregate));
        write_text(out / "runs.csv", metrics::runs_csv(batches.front().runs));
    } else {
        for (std::size_t i = 0; i < batches.size(); ++i) {
            write_text(out / ("aggregate_" + std::to_string(i + 1) + ".yaml"), metrics::to_yaml(batches[i].aggregate));
            write_text(out / ("runs_" + std::to_string(i + 1) + ".csv"), metrics::runs_csv(batches[i].runs));
        }
    }
    spdlog::info("report: tables written to {}", (out / "tables.md").string());
    int code = 0;
    if (o.figures)
        for (std::size_t i = 0; i < dirs.size(); ++i)
            if (!batches[i].runs.empty()) {
                const fs::path fig_out = dirs.size() == 1 ? out : out / ("batch_" + std::to_string(i + 1));
                code = std::max(code, run_figures(dirs[i], fig_out));
            }
    return code;
}

CLI::App* add_report_command(CLI::App& app, CliContext& ctx, CommandRunner& run) {
    struct Args {
        std::vector<std::string> dirs;
        std::string out;
        bool no_figures{false};
    };
    auto a = std::make_shared<Args>();
    auto* sub = app.add_subcommand("report", "aggregate a Monte Carlo batch: the paper's tables and figures");
    sub->add_option("dirs", a->dirs, "batch directories (gdnav montecarlo --out); several: side by side")->required();
    sub->add_option("--out", a->out, "output folder (default: <first dir>/report)");
    sub->add_flag("--no-figures", a->no_figures, "tables only");
    run = [a, &ctx]() {
        setup_logging("gdnav", ctx.log_level);
        ReportOptions o;
        o.figures = !a->no_figures;
        o.out = a->out;
        std::vector<fs::path> dirs(a->dirs.begin(), a->dirs.end());
        return write_batch_report(dirs, o);
    };
    return sub;
}

}  // namespace gdnav::app
