#include "launch/shm_cleanup.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <set>

#include <spdlog/spdlog.h>

namespace gdnav::launch {

namespace fs = std::filesystem;

bool is_fastdds_shm_name(const std::string& n) {
    return n.rfind("fastrtps_", 0) == 0 || n.rfind("sem.fastrtps_", 0) == 0 || n.rfind("fast_datasharing", 0) == 0 ||
           n.rfind("sem.fast_datasharing", 0) == 0;
}

ShmSnapshot list_fastdds_shm(const fs::path& dir) {
    ShmSnapshot s;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        const std::string n = e.path().filename().string();
        if (is_fastdds_shm_name(n)) s.names.push_back(n);
    }
    return s;
}

namespace {
// Every /dev/shm path that a live process maps or holds open.
std::set<std::string> paths_in_use(const fs::path& dir) {
    std::set<std::string> used;
    const std::string prefix = dir.string() + "/";
    std::error_code ec;
    for (const auto& p : fs::directory_iterator("/proc", ec)) {
        const std::string pid = p.path().filename().string();
        if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos) continue;
        std::ifstream maps(p.path() / "maps");
        std::string line;
        while (std::getline(maps, line)) {
            const auto pos = line.find(prefix);
            if (pos != std::string::npos) {
                std::string path = line.substr(pos);
                if (const auto d = path.find(" (deleted)"); d != std::string::npos) path.resize(d);
                used.insert(path);
            }
        }
        std::error_code ec2;
        for (const auto& fd : fs::directory_iterator(p.path() / "fd", ec2)) {
            std::error_code ec3;
            const auto target = fs::read_symlink(fd.path(), ec3);
            if (!ec3 && target.string().rfind(prefix, 0) == 0) used.insert(target.string());
        }
    }
    return used;
}
}  // namespace

std::vector<std::string> stale_fastdds_shm(std::time_t since, const fs::path& dir) {
    std::vector<std::string> stale;
    const auto used = paths_in_use(dir);
    const uid_t me = geteuid();
    for (const auto& n : list_fastdds_shm(dir).names) {
        const fs::path p = dir / n;
        struct stat st {};
        if (stat(p.c_str(), &st) != 0) continue;
        if (st.st_uid != me) continue;
        if (st.st_ctime < since) continue;  // created before this run started: not ours
        if (used.count(p.string())) continue;
        stale.push_back(n);
    }
    return stale;
}

std::vector<std::string> clean_fastdds_shm(std::time_t since, const fs::path& dir) {
    std::vector<std::string> removed;
    for (const auto& n : stale_fastdds_shm(since, dir)) {
        std::error_code ec;
        if (fs::remove(dir / n, ec)) removed.push_back(n);
    }
    if (!removed.empty()) spdlog::debug("removed {} stale Fast DDS shared-memory files", removed.size());
    return removed;
}

}  // namespace gdnav::launch
