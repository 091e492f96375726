#include "launch/batch/batch_dir.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "config/config.hpp"
#include "files/write_error.hpp"

namespace gdnav::launch::batch {

namespace fs = std::filesystem;

Shard parse_shard(const std::string& text) {
    static const std::regex re(R"((\d{1,6})/(\d{1,6}))");
    std::smatch m;
    if (std::regex_match(text, m, re)) {
        const Shard s{std::stoull(m[1]), std::stoull(m[2])};
        if (s.index >= 1 && s.count >= 1 && s.index <= s.count && s.count <= 100000) return s;
    }
    throw config::ConfigError("montecarlo: --shard must be I/N with 1 <= I <= N <= 100000 (I is 1-based), got '" +
                              text + "'");
}

std::vector<std::uint64_t> shard_runs(std::uint64_t first, std::uint64_t runs, const Shard& s) {
    std::vector<std::uint64_t> out;
    for (std::uint64_t k = s.index - 1; k < runs; k += s.count) out.push_back(first + k);
    return out;
}

std::string run_dir_name(std::uint64_t index) {
    char b[32];
    std::snprintf(b, sizeof(b), "run_%04llu", static_cast<unsigned long long>(index));
    return b;
}

void write_file_atomic(const fs::path& file, const std::string& text) {
    char host[256] = {};
    gethostname(host, sizeof(host) - 1);
    // A temporary of its own per host and process: shards share the folder.
    files::write_whole(file, text, std::string(".tmp.") + host + "." + std::to_string(getpid()));
}

std::string read_text(const fs::path& file) {
    std::ifstream f(file);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

BatchDirInfo read_batch_dir(const fs::path& dir) {
    BatchDirInfo info;
    info.dir = dir;
    if (fs::exists(dir / "scenario.yaml")) info.scenario_text = read_text(dir / "scenario.yaml");
    if (fs::exists(dir / "batch.yaml")) {
        try {
            const YAML::Node b = YAML::LoadFile((dir / "batch.yaml").string());
            const auto u = [&](const char* key) { return b[key] ? b[key].as<std::uint64_t>() : std::uint64_t{0}; };
            info.scenario = b["scenario"] ? b["scenario"].as<std::string>() : "";
            info.generator = b["generator"] ? b["generator"].as<std::string>() : "";
            info.has_range = b["seed"] && b["first"] && b["runs"];
            info.seed = u("seed");
            info.first = u("first");
            info.runs = u("runs");
            info.shards = u("shards");
        } catch (const std::exception&) {
            info.has_range = false;  // an unreadable batch.yaml: no range to check against
        }
    }
    static const std::regex re(R"(shard_(\d+)_of_(\d+)\.yaml)");
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir / "shards", ec)) {
        std::smatch m;
        const std::string name = e.path().filename().string();
        if (std::regex_match(name, m, re)) info.shard_records.push_back(m[1].str() + "/" + m[2].str());
    }
    std::sort(info.shard_records.begin(), info.shard_records.end());
    return info;
}

void write_shard_record(const fs::path& dir, const Shard& s, unsigned jobs, std::size_t runs) {
    fs::create_directories(dir / "shards");
    char host[256] = {};
    gethostname(host, sizeof(host) - 1);
    std::ostringstream o;
    o << "# written by gdnav montecarlo --shard " << s.index << "/" << s.count << "\nshard: " << s.index
      << "\nof: " << s.count << "\nruns: " << runs << "\njobs: " << jobs << "\nhost: " << host << "\n";
    write_file_atomic(dir / "shards" / ("shard_" + std::to_string(s.index) + "_of_" + std::to_string(s.count) + ".yaml"),
                      o.str());
}

}  // namespace gdnav::launch::batch
