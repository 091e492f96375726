// Preparing a batch or shard (launch/batch/batch_prepare.hpp): its folder, records and the runs still to do.
#include "launch/batch/batch_prepare.hpp"

#include <sstream>

#include <spdlog/spdlog.h>

#include "config/config.hpp"
#include "framework/run_config.hpp"
#include "framework/scenario_generator.hpp"
#include "launch/batch/run_files.hpp"
#include "launch/member_process.hpp"
#include "metrics/run_record.hpp"

namespace gdnav::launch::batch {

namespace fs = std::filesystem;
using namespace gdnav::launch;

namespace {

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

}  // namespace

// RUN_DIR/drawn_scenario.yaml: what the scenario's generator drew for this run (framework/scenario_generator.hpp),
// so that `gdnav compare` can tell by its SHA-256 whether two batches flew the same missions. Nothing when the
// scenario has no generator. Written beside the run's outputs: no recorded topic or metric changes.
void write_drawn_scenario(const PreparedBatch& p, std::uint64_t run, const fs::path& run_dir) {
    const YAML::Node drawn = framework::drawn_scenario(p.doc, p.seed, run, (p.dir / "scenario.yaml").string());
    if (!drawn || drawn.IsNull()) return;
    YAML::Emitter em;
    em.SetDoublePrecision(17);
    em << drawn;
    write_file_atomic(run_dir / "drawn_scenario.yaml",
                      "# Scenario drawn for this run by its generator (components reduced to their type); written by "
                      "gdnav montecarlo\n" + std::string(em.c_str()) + "\n");
}

PreparedBatch prepare_batch(const BatchSpec& spec, const framework::ComponentRegistry& reg, const Shard& shard) {
    const std::string text = batch_scenario_text(spec);
    // Validate the whole configuration once (run `first`) before starting anything.
    framework::RunOverrides ro;
    ro.run_index = spec.first;
    const framework::RunConfig rc0 = framework::RunConfig::parse(text, spec.file.string(), ro);
    (void)rc0.build(reg);
    check_started_members(rc0, spec.layout);
    {  // every member's command is found (placeholders of a run in the current directory)
        framework::RunConfig probe = rc0;
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

// Runs of the shard still to do: those without a complete metrics.yaml of this seed and index, or whose files are
// not those the run wrote (run_files.hpp; each such run is named with the reason).
std::vector<std::uint64_t> runs_to_do(const PreparedBatch& p, std::size_t& skipped) {
    std::vector<std::uint64_t> todo;
    skipped = 0;
    for (const std::uint64_t i : p.mine) {
        const fs::path dir = p.dir / "runs" / run_dir_name(i);
        const fs::path m = dir / "metrics.yaml";
        bool done = false;
        if (metrics::run_record_complete(m)) {
            const auto r = metrics::read_run_record(m);
            done = r.seed == p.seed && r.run_index == i;
            if (const std::string damage = done ? run_files_damage(dir, true) : ""; !damage.empty()) {
                spdlog::warn("montecarlo: run {} ({}) is damaged: {}; running it again", i, dir.string(), damage);
                done = false;
            }
        }
        if (done)
            ++skipped;
        else
            todo.push_back(i);
    }
    return todo;
}

}  // namespace gdnav::launch::batch
