#include "run_folders.hpp"

#include <unistd.h>

#include "launch/batch/batch_dir.hpp"

namespace gdnav::testing {

namespace fs = std::filesystem;

fs::path temp_dir(const std::string& tag) {
    static int counter = 0;
    const fs::path p = fs::temp_directory_path() /
                       ("gdnav-test-" + std::to_string(getpid()) + "-" + tag + "-" + std::to_string(counter++));
    fs::remove_all(p);
    fs::create_directories(p);
    return p;
}

std::string run_dir(const fs::path& batch, int i) {
    return (batch / "runs" / launch::batch::run_dir_name(static_cast<std::uint64_t>(i))).string();
}

}  // namespace gdnav::testing
