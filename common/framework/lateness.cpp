#include "framework/lateness.hpp"

#include <algorithm>
#include <fstream>

#include <spdlog/spdlog.h>

namespace gdnav::framework {

void Lateness::add(std::int64_t late) {
    per_step.push_back(late);
    if (late < 0) {
        ++missing;
        return;
    }
    ++used;
    sum += static_cast<std::uint64_t>(late);
    max = std::max(max, static_cast<std::uint64_t>(late));
    misses += late > 0;
}

double Lateness::mean() const { return used ? static_cast<double>(sum) / static_cast<double>(used) : 0.0; }

void report_lateness(const std::string& member, const std::vector<std::pair<std::string, const Lateness*>>& inputs,
                     const std::filesystem::path& out_dir) {
    std::string yaml;
    for (const auto& [topic, s] : inputs) {
        spdlog::info("[{}] free-running input '{}': {} steps used a sample, {} had none yet; lateness mean {:.2f} steps, "
                     "max {} steps; deadline misses {} ({:.1f} %)",
                     member, topic, s->used, s->missing, s->mean(), s->max, s->misses,
                     s->used ? 100.0 * static_cast<double>(s->misses) / static_cast<double>(s->used) : 0.0);
        yaml += fmt::format("  {}: {{used: {}, no_sample: {}, mean_steps: {:.4f}, max_steps: {}, misses: {}, per_step: [",
                            topic, s->used, s->missing, s->mean(), s->max, s->misses);
        for (std::size_t i = 0; i < s->per_step.size(); ++i) {
            if (i) yaml += ',';
            yaml += std::to_string(s->per_step[i]);
        }
        yaml += "]}\n";
    }
    if (yaml.empty() || out_dir.empty()) return;
    std::error_code ec;
    const auto dir = out_dir / "lateness";
    std::filesystem::create_directories(dir, ec);
    std::ofstream f(dir / (member + ".yaml"));
    f << "# lateness of free-running inputs at each step of " << member << " (steps; -1 = no sample yet)\ninputs:\n"
      << yaml;
}

}  // namespace gdnav::framework
