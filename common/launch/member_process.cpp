#include "launch/member_process.hpp"

#include <fcntl.h>
#include <openssl/evp.h>
#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <regex>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "launch/children.hpp"

extern char** environ;

namespace gdnav::launch {

namespace fs = std::filesystem;
using config::ConfigError;

namespace {

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
    return s;
}

// {domain}, {run}, {out}, {security} of the run.
std::string substitute(const std::string& s, const framework::RunConfig& rc) {
    std::string r = replace_all(s, "{domain}", std::to_string(rc.domain_id));
    r = replace_all(r, "{run}", std::to_string(rc.info.run_index));
    r = replace_all(r, "{out}", fs::absolute(rc.out_dir).lexically_normal().string());
    return replace_all(r, "{security}", rc.security_dir.string());
}

[[noreturn]] void fail(const framework::RunConfig& rc, const std::string& key, const std::string& what) {
    throw ConfigError("config error: " + rc.origin + ": key 'run.members." + key + "': " + what);
}

bool executable_file(const fs::path& p) {
    std::error_code ec;
    return fs::is_regular_file(p, ec) && access(p.c_str(), X_OK) == 0;
}

// argv[0] as exec would find it: a path (relative to the member's cwd) or a name looked up on PATH.
fs::path resolve_exe(const std::string& word, const fs::path& cwd) {
    if (word.find('/') != std::string::npos) {
        const fs::path p = fs::path(word).is_absolute() ? fs::path(word) : cwd / word;
        return executable_file(p) ? p.lexically_normal() : fs::path();
    }
    const char* path_env = std::getenv("PATH");
    std::string path = path_env ? path_env : "/usr/bin:/bin";
    for (std::size_t start = 0; start <= path.size();) {
        std::size_t end = path.find(':', start);
        if (end == std::string::npos) end = path.size();
        const std::string dir = path.substr(start, end - start);
        const fs::path p = (dir.empty() ? cwd : fs::path(dir)) / word;
        if (executable_file(p)) return fs::absolute(p).lexically_normal();
        start = end + 1;
    }
    return {};
}

// The file the member runs: the script of an interpreter (`python3 -u x.py` runs x.py), else the executable.
fs::path file_run(const fs::path& exe, const std::vector<std::string>& argv, const fs::path& cwd) {
    static const std::regex interpreter(R"((python|pypy)[0-9.]*|bash|sh|dash|zsh|ksh|perl|ruby|node|Rscript|julia)");
    if (!std::regex_match(exe.filename().string(), interpreter)) return exe;
    for (std::size_t i = 1; i < argv.size(); ++i) {
        if (argv[i].rfind('-', 0) == 0) continue;
        const fs::path p = fs::path(argv[i]).is_absolute() ? fs::path(argv[i]) : cwd / argv[i];
        std::error_code ec;
        return fs::is_regular_file(p, ec) ? p.lexically_normal() : exe;
    }
    return exe;
}

}  // namespace

void check_started_members(const framework::RunConfig& rc, const std::string& layout) {
    for (const auto& m : framework::started_members(rc)) {
        if (layout == "direct")
            fail(rc, m.name, "a process member needs the lockstep clock; use --layout composed or distributed (the "
                             "direct layout has no transport)");
    }
}

std::vector<MemberProcess> resolve_member_processes(const framework::RunConfig& rc) {
    std::vector<MemberProcess> out;
    for (const auto& s : framework::started_members(rc)) {
        if (s.in_process()) continue;
        MemberProcess m;
        m.name = s.name;
        for (const auto& a : s.command) m.argv.push_back(substitute(a, rc));
        m.cwd = fs::absolute(s.cwd.empty() ? fs::current_path() : fs::path(substitute(s.cwd, rc))).lexically_normal();
        std::error_code ec;
        if (!fs::is_directory(m.cwd, ec)) fail(rc, s.name + ".cwd", "'" + m.cwd.string() + "' is not a directory");
        m.exe = resolve_exe(m.argv.front(), m.cwd);
        if (m.exe.empty())
            fail(rc, s.name + ".command",
                 "'" + m.argv.front() + "' is not an executable file" +
                     (m.argv.front().find('/') == std::string::npos ? " on PATH" : " (from " + m.cwd.string() + ")"));
        m.file = file_run(m.exe, m.argv, m.cwd);
        m.sha256 = sha256_of_file(m.file);
        for (const auto& [k, v] : s.env) m.env.emplace_back(k, substitute(v, rc));
        m.env.emplace_back("GDNAV_MEMBER", m.name);
        m.env.emplace_back("GDNAV_DOMAIN", std::to_string(rc.domain_id));
        m.env.emplace_back("GDNAV_RUN", std::to_string(rc.info.run_index));
        m.env.emplace_back("GDNAV_OUT", fs::absolute(rc.out_dir).lexically_normal().string());
        m.env.emplace_back("GDNAV_SECURITY", rc.security_dir.string());
        m.env.emplace_back("GDNAV_DDS_PROFILE", rc.dds_profile.string());
        out.push_back(std::move(m));
    }
    return out;
}

pid_t start_member_process(const MemberProcess& m, const fs::path& out_dir) {
    fs::create_directories(out_dir / "logs");
    const fs::path log = out_dir / "logs" / (m.name + ".log");
    std::vector<std::string> env_text;
    for (char** e = environ; *e; ++e) {
        const std::string kv = *e;
        bool replaced = false;
        for (const auto& [k, v] : m.env) replaced = replaced || kv.rfind(k + "=", 0) == 0;
        if (!replaced) env_text.push_back(kv);
    }
    for (const auto& [k, v] : m.env)
        if (!(k == "GDNAV_SECURITY" && v.empty())) env_text.push_back(k + "=" + v);
    SpawnOptions o;
    o.log = log;
    o.cwd = m.cwd;
    o.env = &env_text;
    return spawn_argv(m.exe, m.argv, o);
}

std::string member_process_record(const MemberProcess& m, pid_t pid) {
    YAML::Emitter em;
    em << YAML::Flow << YAML::BeginMap << YAML::Key << m.name << YAML::Value << YAML::BeginMap;
    em << YAML::Key << "pid" << YAML::Value << pid << YAML::Key << "command" << YAML::Value << m.argv;
    em << YAML::Key << "cwd" << YAML::Value << m.cwd.string() << YAML::Key << "executable" << YAML::Value
       << m.exe.string() << YAML::Key << "file" << YAML::Value << m.file.string() << YAML::Key << "sha256"
       << YAML::Value << m.sha256;
    em << YAML::EndMap << YAML::EndMap;
    std::string s = em.c_str();
    // One line per member, as the other entries of processes.yaml: "{NAME: {...}}" without the outer braces.
    return s.substr(1, s.size() - 2);
}

std::string sha256_of_file(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + file.string() + " to hash it");
    std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)> ctx(EVP_MD_CTX_new(), &EVP_MD_CTX_free);
    if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1)
        throw std::runtime_error("OpenSSL SHA-256 unavailable");
    char buf[65536];
    while (in.read(buf, sizeof(buf)) || in.gcount() > 0)
        EVP_DigestUpdate(ctx.get(), buf, static_cast<std::size_t>(in.gcount()));
    unsigned char md[EVP_MAX_MD_SIZE];
    unsigned int n = 0;
    EVP_DigestFinal_ex(ctx.get(), md, &n);
    static const char* hex = "0123456789abcdef";
    std::string s;
    for (unsigned int i = 0; i < n; ++i) {
        s += hex[md[i] >> 4];
        s += hex[md[i] & 15];
    }
    return s;
}

}  // namespace gdnav::launch
