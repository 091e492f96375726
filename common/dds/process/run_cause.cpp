#include "dds/process/run_cause.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <string>

namespace gdnav::dds {

void tell_launcher(std::string_view line) {
    const char* env = std::getenv(kCauseFdEnv);
    if (!env || !*env) return;
    const int fd = std::atoi(env);
    if (fd <= 2) return;
    std::string text(line.substr(0, std::min(line.find('\n'), std::string_view::size_type{1000})));
    text += '\n';
    while (::write(fd, text.data(), text.size()) < 0 && errno == EINTR) {
    }
}

CausePipe::CausePipe() {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC | O_NONBLOCK) != 0) return;  // without it, a failed run names the failed process only
    read_fd_ = fds[0];
    // The write end is inherited by every child (the read end is not): cleared close-on-exec, named in the
    // environment the children copy.
    write_fd_ = fds[1];
    ::fcntl(write_fd_, F_SETFD, 0);
    ::setenv(kCauseFdEnv, std::to_string(write_fd_).c_str(), 1);
}

CausePipe::~CausePipe() {
    if (write_fd_ >= 0) {
        ::unsetenv(kCauseFdEnv);
        ::close(write_fd_);
    }
    if (read_fd_ >= 0) ::close(read_fd_);
}

std::vector<std::string> CausePipe::read_lines() {
    std::vector<std::string> lines;
    if (read_fd_ < 0) return lines;
    char buf[4096];
    while (true) {
        const ssize_t n = ::read(read_fd_, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        pending_.append(buf, static_cast<std::size_t>(n));
    }
    for (std::size_t nl; (nl = pending_.find('\n')) != std::string::npos; pending_.erase(0, nl + 1))
        lines.push_back(pending_.substr(0, nl));
    return lines;
}

}  // namespace gdnav::dds
