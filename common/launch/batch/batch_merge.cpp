#include "launch/batch/batch_merge.hpp"

#include <algorithm>
#include <map>

#include <spdlog/spdlog.h>

#include "launch/batch/batch_dir.hpp"
#include "launch/batch/run_files.hpp"
#include "config/config.hpp"

namespace gdnav::launch::batch {

namespace fs = std::filesystem;

namespace {

// Why two batch directories are not the same batch ("" when they are): scenario.yaml (scenario, overrides, seed,
// steps) and the run range decide; the seed and scenario name only make the message clearer.
std::string difference(const BatchDirInfo& a, const BatchDirInfo& b) {
    if (a.scenario_text != b.scenario_text) {
        if (a.has_range && b.has_range && a.seed != b.seed)
            return "seed " + std::to_string(a.seed) + " vs " + std::to_string(b.seed);
        if (a.generator != b.generator || a.scenario != b.scenario)
            return "scenario '" + a.scenario + "' vs '" + b.scenario + "'";
        return "configuration: scenario.yaml differs (overrides or steps)";
    }
    if (a.has_range != b.has_range || a.first != b.first || a.runs != b.runs)
        return "run range " + std::to_string(a.first) + "+" + std::to_string(a.runs) + " vs " +
               std::to_string(b.first) + "+" + std::to_string(b.runs);
    return "";
}

// Run index -> metrics.yaml of the complete runs of one directory.
std::map<std::uint64_t, fs::path> complete_run_files(const fs::path& dir) {
    std::map<std::uint64_t, fs::path> out;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir / "runs", ec)) {
        const fs::path f = e.path() / "metrics.yaml";
        if (!e.is_directory() || !fs::exists(f)) continue;
        try {
            const metrics::RunRecord r = metrics::read_run_record(f);
            if (r.complete) out.emplace(r.run_index, f);
        } catch (const config::ConfigError& err) {
            spdlog::warn("skipping {}: {}", f.string(), err.what());
        }
    }
    return out;
}

bool lacks_runs(const BatchDirInfo& info) {
    if (!info.has_range) return false;
    const auto found = complete_run_files(info.dir);
    for (std::uint64_t i = info.first; i < info.first + info.runs; ++i)
        if (!found.count(i)) return true;
    return false;
}

}  // namespace

std::vector<std::vector<fs::path>> group_batch_dirs(const std::vector<fs::path>& dirs) {
    std::vector<BatchDirInfo> infos;
    for (const auto& d : dirs) {
        if (!fs::is_directory(d / "runs")) throw config::ConfigError("report: " + d.string() + " holds no runs/ folder");
        infos.push_back(read_batch_dir(d));
    }
    bool one_batch = true;
    for (std::size_t i = 1; i < infos.size() && one_batch; ++i) one_batch = difference(infos[0], infos[i]).empty();
    if (one_batch) return {dirs};
    for (std::size_t i = 0; i < infos.size(); ++i) {
        if (infos[i].shards == 0 || !lacks_runs(infos[i])) continue;
        for (std::size_t j = 0; j < infos.size(); ++j) {
            const std::string why = difference(infos[i], infos[j]);
            if (!why.empty())
                throw config::ConfigError("report: " + dirs[i].string() + " (a shard) and " + dirs[j].string() +
                                          " are not of the same batch (" + why +
                                          "); give the shards of one batch, or whole batches side by side");
        }
    }
    std::vector<std::vector<fs::path>> groups;
    for (const auto& d : dirs) groups.push_back({d});
    return groups;
}

MergedRuns merge_complete_runs(const std::vector<fs::path>& dirs) {
    std::map<std::uint64_t, fs::path> chosen;
    MergedRuns m;
    for (const auto& d : dirs)
        for (const auto& [index, file] : complete_run_files(d)) {
            const auto [it, fresh] = chosen.emplace(index, file);
            if (fresh) continue;
            if (read_text(it->second) != read_text(file))
                throw config::ConfigError("report: run " + std::to_string(index) + " differs between " +
                                          it->second.string() + " and " + file.string() +
                                          " (not the same batch, or not reproducible)");
            m.duplicates.push_back(index);
        }
    for (const auto& [index, file] : chosen) {
        // A run the batch recorded (files.yaml) whose files have changed since is refused, named in one line; runs
        // of a batch older than files.yaml are read as they are (docs/montecarlo.md, "Damaged runs and a full disk").
        const fs::path dir = file.parent_path();
        if (fs::exists(dir / kRunFilesName))
            if (const std::string damage = run_files_damage(dir, false); !damage.empty())
                throw config::ConfigError("report: run " + std::to_string(index) + " (" + dir.string() +
                                          ") is damaged: " + damage +
                                          "; run the batch's gdnav montecarlo command again to rerun it");
        m.runs.push_back(metrics::read_run_record(file));
    }
    const BatchDirInfo info = read_batch_dir(dirs.front());
    if (info.has_range)
        for (std::uint64_t i = info.first; i < info.first + info.runs; ++i)
            if (!chosen.count(i)) m.missing.push_back(i);
    std::sort(m.duplicates.begin(), m.duplicates.end());
    m.duplicates.erase(std::unique(m.duplicates.begin(), m.duplicates.end()), m.duplicates.end());
    return m;
}

std::string index_ranges(const std::vector<std::uint64_t>& v) {
    std::string out;
    for (std::size_t i = 0; i < v.size();) {
        std::size_t j = i;
        while (j + 1 < v.size() && v[j + 1] == v[j] + 1) ++j;
        if (!out.empty()) out += ", ";
        out += std::to_string(v[i]);
        if (j > i) {
            out += '-';
            out += std::to_string(v[j]);
        }
        i = j + 1;
    }
    return out;
}

}  // namespace gdnav::launch::batch
