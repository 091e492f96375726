#pragma once
// A batch run is complete only when its files are: the batch writes RUN_DIR/files.yaml (every result file of the run
// folder, logs left out, with its size and FNV-1a 64 digest) when the run has ended well, and checks it before it counts the run as done
// (a resume) or reports on it (gdnav report). docs/montecarlo.md, "Damaged runs and a full disk".
#include <filesystem>
#include <string>

namespace gdnav::launch::batch {

inline constexpr const char* kRunFilesName = "files.yaml";

// Writes RUN_DIR/files.yaml (whole or not at all; files::WriteError otherwise).
void write_run_files(const std::filesystem::path& run_dir);

// Why the run folder does not hold the files its files.yaml lists ("" when it does): a missing files.yaml, a file
// missing, of another size or (with digests) another digest. Without digests only the sizes are compared.
[[nodiscard]] std::string run_files_damage(const std::filesystem::path& run_dir, bool digests);

}  // namespace gdnav::launch::batch
