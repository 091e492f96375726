#pragma once
// Removes the Fast DDS shared-memory files (/dev/shm/fastrtps_*, sem.fastrtps_*, fast_datasharing_*) that a run
// left behind (Fast DDS leaves them after SIGKILL). Only files that are owned by this user, were created at or after
// `since` (the run's start) and are neither mapped nor open by any live process are removed, so other users' and
// other live runs' segments are never touched.
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

namespace gdnav::launch {

struct ShmSnapshot {
    std::vector<std::string> names;
};

bool is_fastdds_shm_name(const std::string& name);
// Fast DDS files in `dir` (default /dev/shm).
ShmSnapshot list_fastdds_shm(const std::filesystem::path& dir = "/dev/shm");
// Stale files as described above (listed, not removed).
std::vector<std::string> stale_fastdds_shm(std::time_t since, const std::filesystem::path& dir = "/dev/shm");
// Removes stale files as described above; returns the names removed.
std::vector<std::string> clean_fastdds_shm(std::time_t since, const std::filesystem::path& dir = "/dev/shm");

}  // namespace gdnav::launch
