#include "files/write_error.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace gdnav::core::files {

WriteError::WriteError(const std::filesystem::path& file, const std::string& os_error, const std::string& context)
    : std::runtime_error(context + "cannot write " + file.string() + ": " + os_error),
      file_(file),
      os_error_(os_error) {}

void throw_write_error(const std::filesystem::path& file, int errnum) {
    throw WriteError(file, std::strerror(errnum));
}

namespace {

// 0 when all of TEXT reached FD (short writes retried), else the errno of the write that failed.
int write_fd(int fd, std::string_view text) {
    while (!text.empty()) {
        const ssize_t n = ::write(fd, text.data(), text.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return n < 0 ? errno : EIO;
        text.remove_prefix(static_cast<std::size_t>(n));
    }
    return 0;
}

}  // namespace

void write_all(int fd, const std::filesystem::path& file, std::string_view text) {
    if (const int err = write_fd(fd, text); err != 0) throw_write_error(file, err);
}

void write_whole(const std::filesystem::path& file, std::string_view text, std::string_view tmp_suffix) {
    const std::filesystem::path tmp = file.string() + std::string(tmp_suffix);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) throw_write_error(file, errno);
    int err = write_fd(fd, text);
    if (::close(fd) != 0 && err == 0) err = errno;
    if (err == 0 && ::rename(tmp.c_str(), file.c_str()) != 0) err = errno;
    if (err != 0) {
        ::unlink(tmp.c_str());
        throw_write_error(file, err);
    }
}

}  // namespace gdnav::core::files
