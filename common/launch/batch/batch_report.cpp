#include "launch/batch/batch_report.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

#include <spdlog/spdlog.h>

#include "launch/batch/batch_dir.hpp"
#include "launch/batch/batch_failures.hpp"
#include "launch/batch/batch_merge.hpp"
#include "config/config.hpp"
#include "metrics/report_tables.hpp"
#include "framework/lockstep.hpp"
#include "framework/run_config.hpp"

namespace gdnav::launch::batch {

namespace fs = std::filesystem;

namespace {

// Label of a batch in the tables: its folder's name, with "#1" / "#2" for the paper scenarios (the paper's names of
// its two scenarios) or the scenario's name when it differs from the folder's, so two batches of one scenario differ.
std::string batch_label(const fs::path& dir) {
    fs::path norm = fs::absolute(dir).lexically_normal();
    if (norm.filename().empty()) norm = norm.parent_path();  // "out/mc2/"
    const std::string folder = norm.filename().string();
    std::string what;
    try {
        const config::Config b = config::Config::load(dir / "batch.yaml");
        const std::string gen = b.get_string("generator", "");
        what = gen == "paper_scenario1" ? "#1" : gen == "paper_scenario2" ? "#2" : b.get_string("scenario", "");
    } catch (const std::exception&) {
    }
    return what.empty() || what == folder ? folder : folder + " (" + what + ")";
}

// report.py reads one batch folder: for a block of several directories (shards), a folder of links to their runs.
fs::path runs_view(const std::vector<fs::path>& dirs, const std::vector<metrics::RunRecord>& runs, const fs::path& at) {
    if (dirs.size() == 1) return dirs.front();
    std::error_code ec;
    fs::remove_all(at, ec);
    fs::create_directories(at / "runs");
    for (const auto& r : runs)
        for (const auto& d : dirs) {
            const fs::path run = fs::absolute(d / "runs" / run_dir_name(r.run_index));
            if (fs::exists(run / "metrics.yaml")) {
                fs::create_directory_symlink(run, at / "runs" / run_dir_name(r.run_index));
                break;
            }
        }
    return at;
}

void write_text(const fs::path& p, const std::string& text) {
    std::ofstream f(p, std::ios::trunc);
    f << text;
    if (!f) throw std::runtime_error("cannot write " + p.string());
}

// Runs whose estimator stopped before the end (killed, lost) are counted, but their finals are at their last
// estimate: a line of the preamble and a warning name them.
std::string stopped_estimates_note(const std::vector<metrics::RunRecord>& runs, const std::string& where) {
    std::string list;
    std::size_t n = 0;
    for (const auto& r : runs)
        if (!r.estimates_complete) {
            if (n++ > 0) list += ", ";
            list += std::to_string(r.run_index);
            list += " (t_end = " + metrics::fixed(r.t_end_s, 2, false) + " s)";
        }
    if (n == 0) return "";
    spdlog::warn("report: {}: {} run(s) with an estimator that stopped before the end; their final figures are at "
                 "their last estimate: {}", where, n, list);
    return "  - " + std::to_string(n) + " of them with an estimator that stopped before the end (metrics.yaml "
           "`estimates_complete: false`): their figures cover [0, t_end], finals at t_end, % of the distance flown up "
           "to t_end: runs " + list + "\n";
}

// The runs of a block that failed (their failure.yaml, batch_failures.hpp): a line of the preamble, a warning, and
// their last log lines appended to `md`.
std::string failed_runs_note(const std::vector<fs::path>& group, const std::string& where, std::string& md) {
    std::vector<RunFailure> failed;
    for (const auto& d : group)
        for (auto& f : read_run_failures(d)) failed.push_back(std::move(f));
    if (failed.empty()) return "";
    std::string list;
    for (const auto& f : failed)
        list += (list.empty() ? "" : "; ") + std::to_string(f.run) + " (exit code " + std::to_string(f.exit_code) +
                ": " + f.cause + ")";
    spdlog::warn("report: {}: {} failed run(s): {}", where, failed.size(), list);
    md += failures_markdown(failed, where);
    return "  - failed runs (last log lines at the end): " + list + "\n";
}

}  // namespace

int run_report_tool(const std::string& name, std::vector<std::string> args, bool log_failure) {
    const char* py_env = std::getenv("GDNAV_PYTHON");
    const char* script_env = std::getenv("GDNAV_REPORT_SCRIPT");
    const std::string py = py_env && *py_env ? py_env : "/usr/bin/python3";
    const fs::path report = script_env && *script_env
                                ? fs::path(script_env)
                                : framework::config_dir().parent_path() / "tools/report/report.py";
    const fs::path script = name == "report.py" ? report : report.parent_path() / name;
    if (!fs::exists(script)) {
        spdlog::error("{}: {} not found (set GDNAV_REPORT_SCRIPT)", name, script.string());
        return 1;
    }
    args.insert(args.begin(), {py, script.string()});
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
    // Exit code 6: the tool could not write a file and its own last line names it (docs/runtime.md, "Exit codes");
    // a second line here would bury it.
    if (code != 0 && code != framework::kExitWriteFailed && log_failure)
        spdlog::error("{}: {} {} failed with code {}", name, py, script.string(), code);
    return code;
}

int write_batch_report(const std::vector<fs::path>& dirs, const ReportOptions& o, std::vector<std::size_t>* counts) {
    if (dirs.empty()) throw config::ConfigError("report: no batch directory given");
    const std::vector<std::vector<fs::path>> groups = group_batch_dirs(dirs);
    const fs::path out = o.out.empty() ? dirs.front() / "report" : o.out;
    fs::create_directories(out);
    std::vector<metrics::LabelledBatch> batches;
    std::string preamble = "# Aggregated navigation system error (NSE)\n\n";
    std::string failures_md;  // the failed runs' last log lines, after the tables
    for (const auto& group : groups) {
        metrics::LabelledBatch b;
        b.label = batch_label(group.front());
        MergedRuns merged = merge_complete_runs(group);
        b.runs = std::move(merged.runs);
        b.aggregate = metrics::aggregate_runs(b.runs);
        if (counts) counts->push_back(b.runs.size());
        std::string where;
        for (const auto& d : group) where += (where.empty() ? "" : ", ") + d.string();
        preamble += "- " + b.label + ": " + std::to_string(b.runs.size()) + " complete runs in " + where;
        if (!merged.missing.empty()) {
            preamble += " (missing runs: " + index_ranges(merged.missing) + ")";
            spdlog::warn("report: {}: {} run(s) of the batch missing or incomplete: {}", where, merged.missing.size(),
                         index_ranges(merged.missing));
        }
        preamble += '\n';
        preamble += failed_runs_note(group, where, failures_md);
        preamble += stopped_estimates_note(b.runs, where);
        if (!merged.duplicates.empty())
            spdlog::warn("report: {}: run(s) {} found in more than one directory (identical metrics, counted once)",
                         where, index_ranges(merged.duplicates));
        if (b.runs.empty()) spdlog::warn("report: no complete run in {}", where);
        batches.push_back(std::move(b));
    }
    preamble += "\nAggregated metrics: mean, population std and max (largest |value|, sign kept; for per-run maxima "
                "mean and std of |max|) across runs of each per-run metric (t in [0, t_end]). Final: value at t_end. "
                "Distance: true ground distance since t_GNSS; % = 100 · error / distance per run, then aggregated.\n";
    write_text(out / "tables.md", metrics::paper_tables_markdown(batches, preamble) + failures_md);
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
        for (std::size_t i = 0; i < groups.size(); ++i)
            if (!batches[i].runs.empty()) {
                const fs::path fig_out = groups.size() == 1 ? out : out / ("batch_" + std::to_string(i + 1));
                const fs::path view = out / ".runs_view";
                const fs::path batch = runs_view(groups[i], batches[i].runs, view);
                code = std::max(code, run_report_tool("report.py", {batch.string(), "--out", fig_out.string()}));
                const std::string csv = batches.size() == 1 ? "runs.csv" : "runs_" + std::to_string(i + 1) + ".csv";
                if (o.review && code != framework::kExitWriteFailed)
                    code = std::max(code, run_report_tool("review.py", {batch.string(), "--out", fig_out.string(),
                                                                        "--tables", (out / "tables.md").string(),
                                                                        "--runs-csv", (out / csv).string()}));
                std::error_code ec;
                fs::remove_all(view, ec);
                // A refused write (a full disk): every further file would meet the same disk, and the tool's line
                // naming the file stays the last one.
                if (code == framework::kExitWriteFailed) return code;
            }
    return code;
}

}  // namespace gdnav::launch::batch
