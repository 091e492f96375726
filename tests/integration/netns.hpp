#pragma once
// Two network namespaces joined by a veth pair (10.231.0.1 in a(), 10.231.0.2 in b()), made for one test and deleted
// with it; needs root and iproute2 (queue_netem: iptables-legacy and gdnav-test-netem too). Used by the two-host tests (two_hosts_test.cpp, plan_test.cpp).
#include <string>
#include <vector>

namespace gdnav::testing {

class Namespaces {
public:
    Namespaces();
    ~Namespaces();
    Namespaces(const Namespaces&) = delete;
    Namespaces& operator=(const Namespaces&) = delete;
    [[nodiscard]] bool ok() const { return ok_; }
    [[nodiscard]] const std::string& a() const { return a_; }
    [[nodiscard]] const std::string& b() const { return b_; }
    // `tc netem` on both ends of the link (e.g. {"delay", "5ms", "loss", "1%"}); empty = remove it.
    bool netem(const std::vector<std::string>& args);
    // Drops `percent` % of the packets each namespace sends (nftables `numgen random`); 0 removes the rule. Works on
    // kernels without sch_netem.
    bool loss(int percent);
    // Delay (+- jitter, uniform), loss and reordering on both ends without sch_netem: an iptables NFQUEUE rule on
    // each veth hands the UDP packets to gdnav-test-netem (tests/faulty_link), which gives each its verdict late.
    // False when the tool was not built or iptables-legacy is missing. Its counts go to <log_dir>/netem_{a,b}.log.
    bool queue_netem(double delay_ms, double jitter_ms, double loss_pct, double reorder_pct,
                     const std::string& log_dir);
    // Stops the tools (every held packet is released) and removes the rules.
    void queue_netem_stop();
    // The link's state on both ends (up = false cuts it).
    bool link(bool up);
    // argv run inside namespace ns (ip netns exec NS ...).
    static std::vector<std::string> in(const std::string& ns, const std::vector<std::string>& argv);

private:
    static bool sh(const std::vector<std::string>& argv);
    std::string a_, b_, va_, vb_;
    bool ok_{false};
    std::vector<int> netem_pids_;
};

// Root and iproute2 are there (else the caller skips).
bool can_make_namespaces();

}  // namespace gdnav::testing
