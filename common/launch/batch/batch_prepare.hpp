#pragma once
// Preparing a batch or shard of gdnav montecarlo: the batch folder (scenario.yaml, batch.yaml, shard records) checked
// against an earlier start, the drawn scenario of each run, and the runs still to do (docs/montecarlo.md).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "framework/registry.hpp"
#include "launch/batch/batch_dir.hpp"
#include "launch/batch/batch_runner.hpp"

namespace gdnav::launch::batch {

// The batch as validated and recorded in its directory.
struct PreparedBatch {
    std::filesystem::path dir;
    std::uint64_t seed{0};
    double sim_per_run_s{0.0};
    std::vector<std::uint64_t> mine;  // this shard's run indices
    int first_domain{-1};             // >= 0: slot k runs on DDS domain first_domain + k
    YAML::Node doc;                   // DIR/scenario.yaml's document
};

// Validates the batch (every component built once), writes or checks its folder and records.
PreparedBatch prepare_batch(const BatchSpec& spec, const framework::ComponentRegistry& reg, const Shard& shard);

// RUN_DIR/drawn_scenario.yaml: what the scenario's generator draws for run RUN.
void write_drawn_scenario(const PreparedBatch& p, std::uint64_t run, const std::filesystem::path& run_dir);

// Runs of the shard still to do; SKIPPED: the complete ones.
std::vector<std::uint64_t> runs_to_do(const PreparedBatch& p, std::size_t& skipped);

}  // namespace gdnav::launch::batch
