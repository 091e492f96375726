#pragma once
// A Monte Carlo batch, or one shard of it, run as parallel `gdnav run` child processes into a batch directory
// (batch_dir.hpp), resumably (complete runs of the same seed are kept), with a live progress line on stderr.
// Each run: <exe> run --scenario DIR/scenario.yaml --seed S --run i --layout L --out DIR/runs/run_000i
//           [--domain D] --log-level LEVEL
// where <exe> is this program (/proc/self/exe) and D, when a first domain is given, the domain of the run's
// parallel slot.
#include <cstdint>
#include <filesystem>
#include <string>

#include <yaml-cpp/yaml.h>

#include "framework/registry.hpp"
#include "launch/batch/batch_dir.hpp"

namespace gdnav::launch::batch {

struct BatchSpec {
    std::string scenario;         // as given on the command line (recorded in batch.yaml)
    std::filesystem::path file{};  // the scenario file
    YAML::Node doc{};             // its document with the command-line overrides applied
    std::uint64_t seed{1};
    bool seed_given{false};       // seed replaces the document's run.seed (else used only when the file has none)
    std::uint64_t steps{0};       // > 0: every run's number of steps (replaces run.duration_s)
    std::uint64_t first{0};
    std::uint64_t runs{1};
    unsigned jobs{2};             // runs in parallel (recorded in batch.yaml for a whole batch)
    std::string layout{"direct"};
    int domain{-1};               // >= 0 (--domain): slot k of `jobs` runs on DDS domain domain + k; else each run
                                  // takes a domain no other run of this host uses, or the document's run.domain_id
    std::filesystem::path out{};  // the batch directory
    std::string log_level{"info"};
};

// Runs shard `s` of the batch (Shard{} = every run) into spec.out and returns 0 when each of its runs is complete,
// 1 when some failed, 130 when interrupted; configuration errors throw config::ConfigError before anything runs.
// No report.
int run_batch_shard(const BatchSpec& spec, const framework::ComponentRegistry& reg, const Shard& s);

}  // namespace gdnav::launch::batch
