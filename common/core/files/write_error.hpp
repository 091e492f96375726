#pragma once
// Output files written whole or not at all, and the one error every writer throws when the operating system refuses
// a write (docs/runtime.md "Exit codes": such a run ends with exit code 6 and one line naming the file and the OS
// error, e.g. "cannot write out/run.h5: No space left on device").
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace gdnav::core::files {

// An output file the operating system would not let us write (full disk, file size limit, I/O error).
class WriteError : public std::runtime_error {
public:
    // CONTEXT (e.g. "member 'nav_recorder' failed at step 3 (t = 0.02 s): ") goes before "cannot write FILE: ...".
    WriteError(const std::filesystem::path& file, const std::string& os_error, const std::string& context = "");
    [[nodiscard]] const std::filesystem::path& file() const { return file_; }
    [[nodiscard]] const std::string& os_error() const { return os_error_; }

private:
    std::filesystem::path file_;
    std::string os_error_;
};

// Throws WriteError for FILE with strerror(ERRNUM).
[[noreturn]] void throw_write_error(const std::filesystem::path& file, int errnum);

// Writes TEXT to FILE whole or not at all: into FILE + TMP_SUFFIX beside it, closed, then renamed over FILE. On any
// error the temporary is removed, FILE is left as it was, and WriteError names FILE. Writers that may share a folder
// across processes or hosts give a suffix of their own.
void write_whole(const std::filesystem::path& file, std::string_view text, std::string_view tmp_suffix = ".tmp");

// Writes TEXT at the end of the open descriptor FD of FILE, all of it (retrying short writes); WriteError otherwise.
void write_all(int fd, const std::filesystem::path& file, std::string_view text);

}  // namespace gdnav::core::files
namespace gdnav { namespace files = core::files; }  // the short name (docs/architecture.md, "Namespaces")
