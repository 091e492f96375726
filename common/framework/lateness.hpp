#pragma once
// Lateness of inputs from free-running producers (hardware-in-the-loop, docs/protocol.md 'Free-running members').
// A consumer computing step k with the newest sample (zero-order hold) records (k - lag) - sample step: 0 when the
// sample is newer than needed, -1 when there is none yet; lateness > 0 is a deadline miss. Once per executed step.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "framework/compat.hpp"

namespace gdnav::framework {

struct Lateness {
    std::uint64_t used{0};     // steps at which a sample was available
    std::uint64_t missing{0};  // steps with no sample yet
    std::uint64_t misses{0};   // used samples with lateness > 0
    std::uint64_t sum{0};
    std::uint64_t max{0};
    std::vector<std::int64_t> per_step;  // lateness per consumer step (-1: no sample yet)

    void add(std::int64_t late);
    [[nodiscard]] double mean() const;
};

// The inputs of one consumer member: one summary log line per input, and <out_dir>/lateness/<member>.yaml with the
// statistics and the per-step series (nothing written when out_dir is empty or there is no input).
void report_lateness(const std::string& member, const std::vector<std::pair<std::string, const Lateness*>>& inputs,
                     const std::filesystem::path& out_dir);

}  // namespace gdnav::framework
