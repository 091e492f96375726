#include "launch/children.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <stdexcept>
#include <thread>

#include "framework/lockstep.hpp"

namespace gdnav::launch {

namespace fs = std::filesystem;

pid_t spawn_argv(const fs::path& exe, const std::vector<std::string>& argv_text, const SpawnOptions& o) {
    std::vector<char*> argv, envp;
    for (const auto& a : argv_text) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    if (o.env) {
        for (const auto& e : *o.env) envp.push_back(const_cast<char*>(e.c_str()));
        envp.push_back(nullptr);
    }
    const int log_flags = O_WRONLY | O_CREAT | O_CLOEXEC | (o.log_truncate ? O_TRUNC : O_APPEND);
    const pid_t parent = getpid();
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        prctl(PR_SET_PDEATHSIG, SIGTERM);  // never outlive the launcher
        if (getppid() != parent) _exit(1);
        if (!o.log.empty()) {
            const int fd = open(o.log.c_str(), log_flags, 0644);
            if (fd >= 0) {
                dup2(fd, STDOUT_FILENO);
                dup2(fd, STDERR_FILENO);
            }
        }
        if (!o.cwd.empty() && chdir(o.cwd.c_str()) != 0) _exit(127);
        if (o.keep_fd >= 0) fcntl(o.keep_fd, F_SETFD, 0);
        if (o.env)
            execve(exe.c_str(), argv.data(), envp.data());
        else
            execv(exe.c_str(), argv.data());
        if (!o.log.empty()) {
            const char msg[] = "gdnav: exec failed\n";
            (void)!write(STDERR_FILENO, msg, sizeof(msg) - 1);
        }
        _exit(127);
    }
    return pid;
}

pid_t spawn(const fs::path& exe, const std::vector<std::string>& args, const SpawnOptions& o) {
    std::vector<std::string> argv{exe.string()};
    argv.insert(argv.end(), args.begin(), args.end());
    return spawn_argv(exe, argv, o);
}

pid_t spawn(const fs::path& exe, const std::vector<std::string>& args, int keep_fd) {
    SpawnOptions o;
    o.keep_fd = keep_fd;
    return spawn(exe, args, o);
}

std::string describe_status(int status) {
    if (WIFEXITED(status)) return "exit code " + std::to_string(WEXITSTATUS(status));
    if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
    return "status " + std::to_string(status);
}

void reap(std::vector<Child>& children, const std::function<void(Child&)>& on_exit) {
    while (true) {
        int st = 0;
        const pid_t pid = waitpid(-1, &st, WNOHANG);
        if (pid <= 0) return;
        for (auto& c : children)
            if (c.pid == pid && c.running) {
                c.running = false;
                c.status = st;
                on_exit(c);
            }
    }
}

bool any_running(const std::vector<Child>& cs) {
    for (const auto& c : cs)
        if (c.running) return true;
    return false;
}

void signal_all(std::vector<Child>& cs, int sig) {
    for (auto& c : cs)
        if (c.running) kill(c.pid, sig);
}

bool wait_all(std::vector<Child>& cs, double seconds, const std::function<void(Child&)>& on_exit) {
    const double end = framework::steady_now_s() + seconds;
    while (any_running(cs) && framework::steady_now_s() < end) {
        reap(cs, on_exit);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    reap(cs, on_exit);
    return !any_running(cs);
}

}  // namespace gdnav::launch
