#include "launch/launcher.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <map>
#include <thread>

#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

#include "files/write_error.hpp"
#include "framework/lockstep.hpp"
#include "framework/run_members.hpp"
#include "dds/process/process_signals.hpp"
#include "dds/process/run_cause.hpp"
#include "dds/security/security.hpp"
#include "launch/children.hpp"
#include "launch/domain_lock.hpp"
#include "launch/pki/identity_check.hpp"
#include "launch/member_process.hpp"
#include "launch/run_outcome.hpp"
#include "launch/shm_cleanup.hpp"

namespace gdnav::launch {

namespace fs = std::filesystem;

namespace {

// Options that cannot work together, before anything else.
void check_layout(const framework::RunConfig& rc, const LaunchOptions& opt) {
    if (opt.layout != "direct" && opt.layout != "composed" && opt.layout != "distributed")
        throw config::ConfigError("unknown layout '" + opt.layout + "' (allowed: direct, composed, distributed)");
    check_started_members(rc, opt.layout);
    if (opt.layout == "direct" && !rc.external.empty())
        throw config::ConfigError("config error: " + rc.origin +
                                  ": key 'run.external': external members need the lockstep clock; use --layout "
                                  "composed or distributed (the direct layout has no transport)");
}

// The resolved document as run.yaml holds it. An in-process Python member's entry records the SHA-256 of its file,
// as processes.yaml does for a started member's program: which code flew is part of the result. (A missing file is
// left to the member's own one-line error.) Without such a member the text is to_yaml()'s as it is; with one, it is
// parsed and re-emitted, and scalars keep their text, so the other keys read the same.
std::string run_yaml_text(const framework::RunConfig& rc) {
    std::string text = rc.to_yaml();
    if (std::none_of(rc.members.begin(), rc.members.end(),
                     [](const framework::MemberSpec& m) { return m.type == framework::kPythonMemberType; }))
        return text;
    YAML::Node doc = YAML::Load(text);
    for (const framework::MemberSpec& m : rc.members) {
        if (m.type != framework::kPythonMemberType) continue;
        YAML::Node c = doc["components"][m.name];
        if (!c["file"]) continue;
        const fs::path file = c["file"].as<std::string>();
        if (fs::is_regular_file(file)) c["sha256"] = sha256_of_file(file);
    }
    YAML::Emitter em;
    em.SetDoublePrecision(17);
    em << doc;
    return std::string(em.c_str()) + "\n";
}

fs::path write_run_yaml(const framework::RunConfig& rc, const LaunchOptions& opt) {
    fs::create_directories(rc.out_dir);
    // The closing line reads the clock's summary of this run: none of an earlier run in this folder may stand in.
    if (opt.start_clock) fs::remove(fs::path(rc.out_dir) / "clock_summary.yaml");
    const fs::path run_yaml = fs::path(rc.out_dir) / "run.yaml";
    const std::string text = run_yaml_text(rc);
    files::write_whole(run_yaml,
                       "# Resolved run configuration written by gdnav run (layout " + opt.layout + ")\n" + text);
    return run_yaml;
}

// Every identity this run starts must be valid before any process starts (one clear error otherwise).
void check_security(const framework::RunConfig& rc, const LaunchOptions& opt) {
    if (!rc.security_dir.empty() && opt.layout == "distributed")
        throw config::ConfigError(
            "config error: " + rc.origin + ": key 'run.security': not with --layout distributed: Fast DDS 2.9.1 "
            "(Debian 12) leaves some secure endpoints unmatched when more than about 3 participants start together "
            "(measured in docs/deployment.md); use --layout composed (the clock and one process)");
    if (rc.security_dir.empty()) return;
    std::vector<std::string> identities{dds::security::kClockIdentity};
    std::vector<std::string> hosted;
    for (const auto& m : rc.members)
        if (!rc.is_external(m.name)) {
            if (opt.layout == "distributed") identities.push_back(m.name);
            hosted.push_back(m.name);
        }
    if (opt.layout == "composed" && !hosted.empty()) identities.push_back(dds::security::process_identity(hosted));
    if (opt.start_clock)  // the members gdnav starts join under their own name
        for (const auto& m : framework::started_members(rc))
            if (!m.in_process()) identities.push_back(m.name);
    for (const auto& id : identities) pki::check_identity(rc.security_dir, id);
    spdlog::info("DDS Security on: {} identities from {} checked (authentication, access control, AES-GCM)",
                 identities.size(), rc.security_dir.string());
}

std::string join(const std::vector<std::string>& v, const char* sep) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : sep) + x;
    return s;
}

std::vector<Child> start_services(const LaunchOptions& opt) {
    std::vector<Child> services;
    for (const auto& [name, argv] : opt.services) {
        std::vector<std::string> rest(argv.begin() + 1, argv.end());
        services.push_back({name, spawn(argv.front(), rest)});
        spdlog::info("started {} (pid {}): {}", name, services.back().pid, join(argv, " "));
    }
    return services;
}

fs::path member_exe(const LaunchOptions& opt) {
    return opt.exe.empty() ? fs::read_symlink("/proc/self/exe") : opt.exe;
}

// Starts the clock and waits until it owns the domain: it heard no other clock (docs/runtime.md, "DDS domains").
// False when it refused (its one line says why), ended, or the wait was interrupted: no member may start then.
bool start_clock(std::vector<Child>& children, const framework::RunConfig& rc, const LaunchOptions& opt,
                 const fs::path& run_yaml) {
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
    children.push_back({framework::kClockName, spawn(member_exe(opt),
                                                     {"clock", "--ready-fd", std::to_string(fds[1]), "--config",
                                                      run_yaml.string(), "--log-level", opt.log_level},
                                                     fds[1])});
    close(fds[1]);
    const double end = framework::steady_now_s() + framework::kClaimLongestS + rc.startup_timeout_s;
    char c = 0;
    ssize_t n = -1;
    pollfd p{fds[0], POLLIN, 0};
    while (n < 0 && !dds::stop_requested() && framework::steady_now_s() < end)
        if (poll(&p, 1, 50) > 0) n = read(fds[0], &c, 1);
    close(fds[0]);
    if (n == 1) return true;
    if (n != 0) kill(children.front().pid, SIGTERM);  // interrupted, or no answer: the clock ends too
    return false;
}

// The clock ended before it owned the domain: its exit code, once it is gone.
int clock_refused(std::vector<Child>& children) {
    int code = 1;
    if (!wait_all(children, 5.0, [&code](Child& c) {
            code = WIFEXITED(c.status) ? WEXITSTATUS(c.status) : 128 + WTERMSIG(c.status);
        })) {
        signal_all(children, SIGKILL);
        reap(children, [](Child&) {});
    }
    return dds::stop_requested() ? framework::kExitInterrupted : code == 0 ? 1 : code;
}

// The members: all (not external), or this host's slice of a plan.
std::vector<Child> start_members(const framework::RunConfig& rc, const LaunchOptions& opt, const fs::path& run_yaml) {
    const fs::path exe = member_exe(opt);
    const std::vector<std::string> common{"--config", run_yaml.string(), "--log-level", opt.log_level};
    auto args = [&](std::vector<std::string> a) {
        a.insert(a.end(), common.begin(), common.end());
        return a;
    };
    auto here = [&](const std::string& name) {
        if (rc.is_external(name)) return false;
        return !opt.slice || std::find(opt.only.begin(), opt.only.end(), name) != opt.only.end();
    };
    std::vector<Child> children;
    if (opt.layout == "distributed") {
        for (const auto& m : rc.members)
            if (here(m.name)) children.push_back({m.name, spawn(exe, args({"component", m.name}))});
    } else {
        std::string all;
        for (const auto& m : rc.members)
            if (here(m.name)) all += (all.empty() ? "" : ",") + m.name;
        if (!all.empty()) children.push_back({"composed", spawn(exe, args({"component", all}))});
    }
    return children;
}

// Starts the process members after the others, says which external members gdnav does not start, and writes
// processes.yaml (a process member's entry with its command and hash).
void start_process_members(std::vector<Child>& children, const std::vector<MemberProcess>& procs,
                           const framework::RunConfig& rc) {
    const std::size_t others = children.size();
    std::vector<std::string> records;
    for (const auto& m : procs) {
        children.push_back({m.name, start_member_process(m, rc.out_dir)});
        records.push_back(member_process_record(m, children.back().pid));
        spdlog::info("started member {} (pid {}): {} (in {}, output in logs/{}.log)", m.name, children.back().pid,
                     join(m.argv, " "), m.cwd.string(), m.name);
    }
    std::vector<std::string> outside;
    const std::vector<framework::StartedMember> given = framework::started_members(rc);
    for (const auto& e : rc.external)
        if (!framework::find_started(given, e)) outside.push_back(e);
    if (!outside.empty())
        spdlog::info("external member(s) {} are not started by gdnav: start them on DDS domain {} with run id {} "
                     "(e.g. `--domain {} --run {}`); waiting up to {:.0f} s",
                     join(outside, ", "), rc.domain_id, rc.info.run_index, rc.domain_id, rc.info.run_index,
                     rc.join_timeout_s);
    std::ofstream f(fs::path(rc.out_dir) / "processes.yaml");
    for (std::size_t i = 0; i < others; ++i) f << children[i].name << ": " << children[i].pid << "\n";
    for (const auto& r : records) f << r << "\n";
}

struct Outcome {
    int clock_code{-1};
    std::vector<std::string> failures;         // "name (how it ended)"
    std::vector<std::string> member_failures;  // of them, the process members gdnav started
    bool interrupted{false};
    bool stopped{false};  // the launcher stopped the run after a member_failure
    bool write_failed{false};         // a process ended with kExitWriteFailed (an output file it could not write)
    std::vector<std::string> causes;  // the lines the processes told the launcher (dds/process/run_cause.hpp)
};

bool is_process_member(const std::vector<MemberProcess>& procs, const std::string& name) {
    return std::any_of(procs.begin(), procs.end(), [&name](const MemberProcess& m) { return m.name == name; });
}

// Waits for the children: Ctrl-C stops them all; once the clock is gone the members get member_timeout_s to end.
// A process member (procs) that fails stops the run.
Outcome supervise(std::vector<Child>& children, const framework::RunConfig& rc,
                  const std::vector<MemberProcess>& procs) {
    Outcome out;
    auto on_exit = [&](Child& c) {
        const bool ok = WIFEXITED(c.status) && WEXITSTATUS(c.status) == 0;
        const bool clock = c.name == framework::kClockName;
        if (clock) out.clock_code = WIFEXITED(c.status) ? WEXITSTATUS(c.status) : 128 + WTERMSIG(c.status);
        if (ok) return;
        out.write_failed =
            out.write_failed || (WIFEXITED(c.status) && WEXITSTATUS(c.status) == framework::kExitWriteFailed);
        // A member that ended with 3 only followed the clock's ABORT, and the clock's own exit code is on the
        // closing line: neither is a cause of its own (logged at debug level).
        const bool follows_clock = WIFEXITED(c.status) && (clock || WEXITSTATUS(c.status) == framework::kExitAborted);
        if (follows_clock) {
            spdlog::debug("process '{}' (pid {}) ended: {}", c.name, c.pid, describe_status(c.status));
            return;
        }
        out.failures.push_back(c.name + " (" + describe_status(c.status) + ")");
        spdlog::warn("process '{}' (pid {}) ended: {}", c.name, c.pid, describe_status(c.status));
        if (is_process_member(procs, c.name) && !out.stopped && !out.interrupted)
            out.member_failures.push_back(out.failures.back());
    };
    while (any_running(children)) {
        reap(children, on_exit);
        if (dds::stop_requested() && !out.interrupted) {
            out.interrupted = true;
            spdlog::warn("interrupted: stopping all processes of the run");
            signal_all(children, SIGTERM);
            if (!wait_all(children, 3.0, on_exit)) signal_all(children, SIGKILL);
        }
        // A member gdnav started that failed fails the run (its outputs are missing): no need to wait for the
        // clock's timeouts.
        if (!out.member_failures.empty() && !out.stopped && !out.interrupted) {
            out.stopped = true;
            spdlog::warn("stopping the run: member {} failed", out.member_failures.front());
            signal_all(children, SIGTERM);
            if (!wait_all(children, 3.0, on_exit)) signal_all(children, SIGKILL);
        }
        if (out.clock_code >= 0 && any_running(children)) {
            if (!wait_all(children, rc.member_timeout_s + 3.0, on_exit)) {
                spdlog::warn("members still running after the clock ended; terminating them");
                signal_all(children, SIGTERM);
                if (!wait_all(children, 2.0, on_exit)) signal_all(children, SIGKILL);
            }
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    reap(children, on_exit);
    return out;
}

void stop_services(std::vector<Child>& services) {
    if (services.empty()) return;
    signal_all(services, SIGTERM);
    if (!wait_all(services, 3.0, [](Child&) {})) signal_all(services, SIGKILL);
    reap(services, [](Child&) {});
}

// The run's exit code from how its processes ended, with the closing log line.
int exit_code(const Outcome& out, const framework::RunConfig& rc, const LaunchOptions& opt,
              const std::vector<MemberProcess>& procs) {
    if (out.interrupted) {
        spdlog::error("run interrupted");
        return framework::kExitInterrupted;
    }
    if (!opt.start_clock) {  // a plan host without the clock: its own processes decide
        if (!out.failures.empty()) {
            spdlog::error("host slice failed: {}", join(out.failures, ", "));
            return 1;
        }
        spdlog::info("host slice completed; results in {}", rc.out_dir);
        return framework::kExitOk;
    }
    ClockSummary summary = read_clock_summary(fs::path(rc.out_dir) / "clock_summary.yaml");
    // No reason in the summary (the clock could not write it, or a member failed after a completed run): the first
    // cause a process told the launcher.
    if (summary.abort_reason.empty() && !out.causes.empty()) summary.abort_reason = out.causes.front();
    std::vector<std::string> members = out.member_failures;  // members gdnav started that failed or were lost
    for (const auto& d : summary.dead)
        if (is_process_member(procs, d.name))
            members.push_back(d.name + " (declared dead at step " + std::to_string(d.step) + ": " + d.reason + ")");
    if (!members.empty()) {
        spdlog::error("run failed: member {}, started by gdnav; its output is in {}/logs/", join(members, ", "),
                      rc.out_dir);
        return 1;
    }
    if (out.clock_code != framework::kExitOk || out.write_failed) {
        // A file that could not be written is the run's cause whatever the clock made of it (docs/runtime.md).
        const int code = out.write_failed ? framework::kExitWriteFailed : out.clock_code > 0 ? out.clock_code : 1;
        spdlog::error("{}", failed_run_line(code, summary, out.failures));
        return code;
    }
    const std::string line = completed_run_line(summary, out.failures, rc.out_dir);
    if (summary.dead.empty() && out.failures.empty())
        spdlog::info("{}", line);
    else
        spdlog::warn("{}", line);
    return framework::kExitOk;
}

}  // namespace

int launch_run(framework::RunConfig rc, const framework::ComponentRegistry& reg, const LaunchOptions& opt) {
    check_layout(rc, opt);
    // Validate everything before anything starts: build (construct + configure) every component.
    (void)rc.build(reg);
    DomainLock domain_lock;  // held until the run's end
    if (opt.layout != "direct") choose_domain(rc, domain_lock);
    const fs::path run_yaml = write_run_yaml(rc, opt);
    spdlog::info("run {} seed {} layout {}: {} steps of {} s -> {}", rc.info.run_index, rc.info.seed, opt.layout,
                 rc.info.steps, rc.info.dt_s, rc.out_dir);
    if (opt.layout == "direct") {
        if (!rc.security_dir.empty())
            spdlog::warn("run.security is ignored in the direct layout (one process, no DDS)");
        return run_direct(rc, reg, true);
    }
    check_security(rc, opt);
    // Process members are started where the clock is (a plan's other hosts start none).
    const std::vector<MemberProcess> procs =
        opt.start_clock ? resolve_member_processes(rc) : std::vector<MemberProcess>{};

    const std::time_t started = std::time(nullptr) - 1;
    dds::install_stop_signal_handlers();
    std::vector<Child> services = start_services(opt);
    dds::CausePipe causes;  // before the clock and the members start: they inherit its write end
    std::vector<Child> children;
    if (opt.start_clock && !start_clock(children, rc, opt, run_yaml)) {
        const int code = clock_refused(children);
        stop_services(services);
        return code;
    }
    for (Child& c : start_members(rc, opt, run_yaml)) children.push_back(c);
    start_process_members(children, procs, rc);
    Outcome out = supervise(children, rc, procs);
    out.causes = causes.read_lines();
    stop_services(services);
    const auto removed = clean_fastdds_shm(started);
    if (!removed.empty()) spdlog::info("removed {} Fast DDS shared-memory files left by the run", removed.size());
    return exit_code(out, rc, opt, procs);
}

}  // namespace gdnav::launch
