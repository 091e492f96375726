#include "netns.hpp"

#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <tuple>

#include "process_util.hpp"

namespace gdnav::testing {

Namespaces::Namespaces()
    : a_("gdnav-a-" + std::to_string(getpid())),
      b_("gdnav-b-" + std::to_string(getpid())),
      va_("gdv" + std::to_string(getpid() % 100000) + "a"),
      vb_("gdv" + std::to_string(getpid() % 100000) + "b") {
    ok_ = sh({"ip", "netns", "add", a_}) && sh({"ip", "netns", "add", b_}) &&
          sh({"ip", "link", "add", va_, "type", "veth", "peer", "name", vb_}) &&
          sh({"ip", "link", "set", va_, "netns", a_}) && sh({"ip", "link", "set", vb_, "netns", b_}) &&
          sh({"ip", "-n", a_, "addr", "add", "10.231.0.1/24", "dev", va_}) &&
          sh({"ip", "-n", b_, "addr", "add", "10.231.0.2/24", "dev", vb_}) && link(true) &&
          sh({"ip", "-n", a_, "link", "set", "lo", "up"}) && sh({"ip", "-n", b_, "link", "set", "lo", "up"});
}

Namespaces::~Namespaces() {
    queue_netem_stop();
    sh({"ip", "netns", "del", a_});
    sh({"ip", "netns", "del", b_});
}

bool Namespaces::netem(const std::vector<std::string>& args) {
    bool ok = true;
    for (const auto& [ns, dev] : {std::pair{a_, va_}, std::pair{b_, vb_}}) {
        sh({"ip", "netns", "exec", ns, "tc", "qdisc", "del", "dev", dev, "root"});  // none yet: fails, fine
        if (args.empty()) continue;
        std::vector<std::string> v{"ip", "netns", "exec", ns, "tc", "qdisc", "add", "dev", dev, "root", "netem"};
        v.insert(v.end(), args.begin(), args.end());
        ok = sh(v) && ok;
    }
    return ok;
}

bool Namespaces::loss(int percent) {
    bool ok = true;
    for (const auto& ns : {a_, b_}) {
        sh({"ip", "netns", "exec", ns, "nft", "delete", "table", "inet", "gdnav_loss"});  // none yet: fails, fine
        if (percent <= 0) continue;
        ok = sh({"ip", "netns", "exec", ns, "nft", "add", "table", "inet", "gdnav_loss"}) &&
             sh({"ip", "netns", "exec", ns, "nft", "add", "chain", "inet", "gdnav_loss", "out",
                 "{ type filter hook output priority 0; }"}) &&
             sh({"ip", "netns", "exec", ns, "nft", "add", "rule", "inet", "gdnav_loss", "out", "meta", "l4proto",
                 "udp", "numgen", "random", "mod", "100", "<", std::to_string(percent), "drop"}) &&
             ok;
    }
    return ok;
}

bool Namespaces::queue_netem(double delay_ms, double jitter_ms, double loss_pct, double reorder_pct,
                             const std::string& log_dir) {
    const std::string exe = GDNAV_TEST_NETEM_EXE;
    if (exe.empty() || !std::filesystem::exists(exe)) return false;
    queue_netem_stop();
    auto num = [](double v) {
        char b[32];
        std::snprintf(b, sizeof(b), "%g", v);
        return std::string(b);
    };
    unsigned seed = 1;
    for (const auto& [ns, dev, tag] : {std::tuple{a_, va_, "a"}, std::tuple{b_, vb_, "b"}}) {
        if (!sh({"ip", "netns", "exec", ns, "iptables-legacy", "-t", "mangle", "-A", "OUTPUT", "-o", dev, "-p", "udp",
                 "-j", "NFQUEUE", "--queue-num", "7", "--queue-bypass"})) {
            queue_netem_stop();
            return false;
        }
        netem_pids_.push_back(start(in(ns, {exe, "--queue", "7", "--delay-ms", num(delay_ms), "--jitter-ms",
                                            num(jitter_ms), "--loss-pct", num(loss_pct), "--reorder-pct",
                                            num(reorder_pct), "--seed", std::to_string(seed++)}),
                                    std::filesystem::path(log_dir) / (std::string("netem_") + tag + ".log")));
    }
    usleep(300000);  // the tools bind their queues (until then --queue-bypass lets packets through)
    for (int pid : netem_pids_)
        if (!alive(pid)) {
            queue_netem_stop();
            return false;
        }
    return true;
}

void Namespaces::queue_netem_stop() {
    for (int pid : netem_pids_) {
        kill(pid, SIGTERM);
        wait_for(pid, 5.0);
    }
    netem_pids_.clear();
    for (const auto& [ns, dev] : {std::pair{a_, va_}, std::pair{b_, vb_}})
        sh({"ip", "netns", "exec", ns, "iptables-legacy", "-t", "mangle", "-D", "OUTPUT", "-o", dev, "-p", "udp",
            "-j", "NFQUEUE", "--queue-num", "7", "--queue-bypass"});  // none: fails, fine
}

bool Namespaces::link(bool up) {
    return sh({"ip", "-n", a_, "link", "set", va_, up ? "up" : "down"}) &&
           sh({"ip", "-n", b_, "link", "set", vb_, up ? "up" : "down"});
}

std::vector<std::string> Namespaces::in(const std::string& ns, const std::vector<std::string>& argv) {
    std::vector<std::string> v{"/usr/bin/env", "ip", "netns", "exec", ns};
    v.insert(v.end(), argv.begin(), argv.end());
    return v;
}

bool Namespaces::sh(const std::vector<std::string>& argv) {
    std::vector<std::string> full{"/usr/bin/env"};
    full.insert(full.end(), argv.begin(), argv.end());
    return run(full, 10.0).exit_code == 0;
}

bool can_make_namespaces() {
    return geteuid() == 0 && (std::filesystem::exists("/usr/bin/ip") || std::filesystem::exists("/sbin/ip"));
}

}  // namespace gdnav::testing
