// files::write_whole and write_all: a file is written whole or left as it was, and a refused write names the file
// and the operating system's error (docs/runtime.md "Exit codes").
#include "files/write_error.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "temp_dir.hpp"

namespace gdnav::core::files {
namespace {

std::string read(const std::filesystem::path& p) {
    std::ifstream f(p);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

TEST(WriteWhole, ReplacesTheFileAndLeavesNoTemporary) {
    const test::TempDir t;
    const auto file = t.path() / "summary.yaml";
    write_whole(file, "a: 1\n");
    write_whole(file, "b: 2\n");
    EXPECT_EQ(read(file), "b: 2\n");
    EXPECT_FALSE(std::filesystem::exists(file.string() + ".tmp"));
}

TEST(WriteWhole, AFolderThatIsNotThereNamesTheFileAndTheError) {
    const test::TempDir t;
    const auto file = t.path() / "missing" / "summary.yaml";
    try {
        write_whole(file, "a: 1\n");
        FAIL() << "no error";
    } catch (const WriteError& e) {
        EXPECT_EQ(e.file(), file);
        EXPECT_EQ(e.os_error(), "No such file or directory");
        EXPECT_EQ(std::string(e.what()), "cannot write " + file.string() + ": No such file or directory");
    }
}

TEST(WriteAll, AFullDeviceIsNoSpaceLeftOnDevice) {
    // /dev/full refuses every write with ENOSPC, as a full file system does.
    const int fd = ::open("/dev/full", O_WRONLY | O_CLOEXEC);
    if (fd < 0) GTEST_SKIP() << "no /dev/full";
    try {
        write_all(fd, "/tmp/out/run.mcap", "bytes");
        FAIL() << "no error";
    } catch (const WriteError& e) {
        EXPECT_EQ(std::string(e.what()), "cannot write /tmp/out/run.mcap: No space left on device");
    }
    ::close(fd);
}

TEST(WriteError, AContextGoesBeforeTheFile) {
    const WriteError e("out/run.h5", "File too large", "member 'nav_recorder' failed at step 3 (t = 0.03 s): ");
    EXPECT_EQ(std::string(e.what()), "member 'nav_recorder' failed at step 3 (t = 0.03 s): cannot write out/run.h5: "
                                     "File too large");
}

}  // namespace
}  // namespace gdnav::core::files
