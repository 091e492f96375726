#include "launch/batch/run_files.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "files/write_error.hpp"
#include "io/recording/record_file.hpp"

namespace gdnav::launch::batch {

namespace fs = std::filesystem;

namespace {

std::string file_digest(const fs::path& file) {
    std::ifstream f(file, std::ios::binary);
    std::uint64_t h = io::recording::kFnvBasis;
    std::vector<char> buf(1 << 16);
    while (f) {
        f.read(buf.data(), static_cast<std::streamsize>(buf.size()));
        h = io::recording::fnv1a(h, reinterpret_cast<const std::uint8_t*>(buf.data()),
                                 static_cast<std::size_t>(f.gcount()));
    }
    return io::recording::digest_hex(h);
}

// The run folder's result files, relative, sorted: files.yaml itself, temporaries and the logs (log.txt, logs/:
// diagnostics, not results) left out.
std::vector<std::string> run_files(const fs::path& run_dir) {
    std::vector<std::string> out;
    for (const auto& e : fs::recursive_directory_iterator(run_dir)) {
        if (!e.is_regular_file()) continue;
        const std::string rel = fs::relative(e.path(), run_dir).generic_string();
        if (rel == kRunFilesName || e.path().extension() == ".tmp" || rel == "log.txt" || rel.rfind("logs/", 0) == 0)
            continue;
        out.push_back(rel);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

void write_run_files(const fs::path& run_dir) {
    std::ostringstream o;
    o << "# The files of this run as it ended (gdnav montecarlo): a run whose files differ is run again.\nfiles:\n";
    for (const auto& rel : run_files(run_dir))
        o << "  \"" << rel << "\": {size: " << fs::file_size(run_dir / rel) << ", digest: \""
          << file_digest(run_dir / rel) << "\"}\n";
    files::write_whole(run_dir / kRunFilesName, o.str());
}

std::string run_files_damage(const fs::path& run_dir, bool digests) {
    const fs::path list = run_dir / kRunFilesName;
    if (!fs::exists(list)) return std::string(kRunFilesName) + " is missing (the run did not end well)";
    YAML::Node doc;
    try {
        doc = YAML::LoadFile(list.string());
    } catch (const YAML::Exception& e) {
        return std::string(kRunFilesName) + " is unreadable (" + e.what() + ")";
    }
    const YAML::Node entries = doc["files"];
    if (!entries || !entries.IsMap()) return std::string(kRunFilesName) + " lists no files";
    for (const auto& e : entries) {
        const std::string rel = e.first.as<std::string>();
        const fs::path file = run_dir / rel;
        std::error_code ec;
        const auto size = fs::file_size(file, ec);
        if (ec) return rel + " is missing";
        const auto want = e.second["size"].as<std::uintmax_t>(0);
        if (size != want)
            return rel + " has " + std::to_string(size) + " bytes, " + std::to_string(want) + " when the run ended";
        if (digests && file_digest(file) != e.second["digest"].as<std::string>(""))
            return rel + " differs from the file the run wrote (digest)";
    }
    return "";
}

}  // namespace gdnav::launch::batch
