#include "process_util.hpp"

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

#include <yaml-cpp/yaml.h>

namespace gdnav::testing {

int free_port() {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) return -1;
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = 0;
    socklen_t n = sizeof(a);
    const bool ok = bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof(a)) == 0 &&
                    getsockname(fd, reinterpret_cast<sockaddr*>(&a), &n) == 0;
    close(fd);
    return ok ? ntohs(a.sin_port) : -1;
}

namespace fs = std::filesystem;

namespace {
double now_s() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
pid_t spawn(const std::vector<std::string>& argv, int out_fd) {
    std::vector<char*> a;
    for (const auto& s : argv) a.push_back(const_cast<char*>(s.c_str()));
    a.push_back(nullptr);
    const pid_t pid = fork();
    if (pid == 0) {
        setpgid(0, 0);
        dup2(out_fd, 1);
        dup2(out_fd, 2);
        execv(a[0], a.data());
        _exit(127);
    }
    return pid;
}
int decode(int st) { return WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st); }
}  // namespace

Result run(const std::vector<std::string>& argv, double timeout_s) {
    const fs::path log = temp_dir("log") / "out.txt";
    const double t0 = now_s();
    const pid_t pid = start(argv, log);
    Result r;
    r.exit_code = wait_for(pid, timeout_s);
    if (r.exit_code == -1) {
        kill(-pid, SIGKILL);
        int st = 0;
        waitpid(pid, &st, 0);
    }
    r.wall_s = now_s() - t0;
    r.output = read_file(log);
    return r;
}

pid_t start(const std::vector<std::string>& argv, const fs::path& log) {
    const int fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const pid_t pid = spawn(argv, fd);
    close(fd);
    return pid;
}

int wait_for(pid_t pid, double timeout_s) {
    const double end = now_s() + timeout_s;
    do {  // checked at least once: a timeout of 0 asks whether it has ended
        int st = 0;
        const pid_t r = waitpid(pid, &st, WNOHANG);
        if (r == pid) return decode(st);
        if (now_s() >= end) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    } while (now_s() < end);
    return -1;
}

bool alive(pid_t pid) {
    if (kill(pid, 0) != 0) return false;
    // A zombie is not alive.
    std::ifstream st("/proc/" + std::to_string(pid) + "/stat");
    std::string s;
    std::getline(st, s);
    const auto p = s.rfind(')');
    return !(p != std::string::npos && p + 2 < s.size() && s[p + 2] == 'Z');
}

bool wait_for_log(pid_t pid, const fs::path& log, const std::string& text, double timeout_s) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
    while (read_file(log).find(text) == std::string::npos) {
        if (!alive(pid) || std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return true;
}

std::size_t count_of(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

std::string read_file(const fs::path& p) {
    std::ifstream f(p);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

std::map<std::string, pid_t> read_processes(const fs::path& out) {
    std::map<std::string, pid_t> m;
    if (!fs::exists(out / "processes.yaml")) return m;
    const YAML::Node n = YAML::LoadFile((out / "processes.yaml").string());
    // A member gdnav started (run.members) is a map with its pid, command and hash.
    for (const auto& kv : n)
        m[kv.first.as<std::string>()] = kv.second.IsMap() ? kv.second["pid"].as<pid_t>() : kv.second.as<pid_t>();
    return m;
}

std::map<std::string, std::string> read_digests(const fs::path& out) {
    std::map<std::string, std::string> m;
    const fs::path f = out / "record" / "digest.yaml";
    if (!fs::exists(f)) return m;
    const YAML::Node n = YAML::LoadFile(f.string());
    for (const auto& kv : n["topics"]) m[kv.first.as<std::string>()] = kv.second["digest"].as<std::string>();
    return m;
}

std::string testchain_exe() { return GDNAV_TESTCHAIN_EXE; }
std::string chain_scenario() { return GDNAV_CHAIN_SCENARIO; }

PairResult run_pair(const std::vector<std::string>& run_argv, const std::vector<std::string>& member_argv,
                    const fs::path& log_base, double timeout_s) {
    const std::string run_log = log_base.string() + ".run.log", member_log = log_base.string() + ".member.log";
    const pid_t launcher = start(run_argv, run_log);
    const pid_t member = start(member_argv, member_log);
    PairResult p;
    p.run_code = wait_for(launcher, timeout_s);
    if (p.run_code == -1) kill(-launcher, SIGKILL);
    p.member_code = wait_for(member, 30.0);
    if (p.member_code == -1) kill(-member, SIGKILL);
    p.run_log = read_file(run_log);
    p.member_log = read_file(member_log);
    return p;
}

int expect_consistent_markdown_tables(const std::string& md) {
    std::istringstream in(md);
    std::string line;
    long cells = -1;
    int tables = 0;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] != '|') {
            cells = -1;
            continue;
        }
        const std::string unescaped = std::regex_replace(line, std::regex(R"(\\\|)"), "");
        const long n = std::count(unescaped.begin(), unescaped.end(), '|');
        if (cells < 0) {
            cells = n;
            ++tables;
        }
        EXPECT_EQ(n, cells) << line;
    }
    return tables;
}

}  // namespace gdnav::testing
