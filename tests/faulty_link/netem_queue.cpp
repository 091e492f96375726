// gdnav-test-netem: a user-space stand-in for `tc netem` on kernels built without sch_netem (as this project's CI
// VMs are): it takes the packets an iptables NFQUEUE rule hands it and gives each a verdict later, so the link gets
// a delay with jitter, random loss and reordering (out-of-order verdicts). Test infrastructure only.
//
//   iptables-legacy -t mangle -A OUTPUT -o VETH -p udp -j NFQUEUE --queue-num Q --queue-bypass
//   gdnav-test-netem --queue Q --delay-ms 5 --jitter-ms 1 --loss-pct 1 --reorder-pct 5 [--seed S]
//
// Each packet is dropped with probability loss (draws from gdnav's rnd::Stream, seeded with --seed); of the others,
// reorder % are released at once (they overtake the held ones, as netem's `reorder`), the rest after
// delay + uniform(-jitter, +jitter). SIGTERM/SIGINT: every held packet is released, the counts are printed on
// stderr, exit 0. With --queue-bypass on the rule, packets pass untouched whenever no program listens on the queue.
#include <arpa/inet.h>
#include <libnetfilter_queue/libnetfilter_queue.h>
#include <linux/netfilter.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <time.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <queue>
#include <string>
#include <vector>

#include "random/stream.hpp"

namespace {

volatile sig_atomic_t g_stop = 0;
void on_signal(int) { g_stop = 1; }

std::int64_t now_ns() {
    timespec t{};
    clock_gettime(CLOCK_MONOTONIC, &t);
    return static_cast<std::int64_t>(t.tv_sec) * 1000000000 + t.tv_nsec;
}

struct Options {
    unsigned queue{0};
    double delay_ms{0}, jitter_ms{0}, loss_pct{0}, reorder_pct{0};
    std::uint64_t seed{1};
};

struct Held {
    std::int64_t release_ns;
    std::uint32_t id;
    bool operator>(const Held& o) const { return release_ns > o.release_ns; }
};

struct State {
    Options opt;
    gdnav::rnd::Stream rng;  // gdnav's own generator (common/core/random), seeded with --seed
    nfq_q_handle* qh{nullptr};
    std::priority_queue<Held, std::vector<Held>, std::greater<>> held;
    std::uint64_t packets{0}, dropped{0}, reordered{0}, delayed{0};
};

int on_packet(nfq_q_handle* qh, nfgenmsg*, nfq_data* nfa, void* data) {
    auto* st = static_cast<State*>(data);
    const nfqnl_msg_packet_hdr* ph = nfq_get_msg_packet_hdr(nfa);
    if (!ph) return 0;
    const std::uint32_t id = ntohl(ph->packet_id);
    ++st->packets;
    if (st->rng.uniform() * 100.0 < st->opt.loss_pct) {
        ++st->dropped;
        return nfq_set_verdict(qh, id, NF_DROP, 0, nullptr);
    }
    if (st->rng.uniform() * 100.0 < st->opt.reorder_pct) {
        ++st->reordered;
        return nfq_set_verdict(qh, id, NF_ACCEPT, 0, nullptr);
    }
    const double d_ms = st->opt.delay_ms + (2.0 * st->rng.uniform() - 1.0) * st->opt.jitter_ms;
    st->held.push({now_ns() + static_cast<std::int64_t>((d_ms > 0 ? d_ms : 0) * 1e6), id});
    ++st->delayed;
    return 0;
}

void release_due(State& st, std::int64_t t) {
    while (!st.held.empty() && st.held.top().release_ns <= t) {
        nfq_set_verdict(st.qh, st.held.top().id, NF_ACCEPT, 0, nullptr);
        st.held.pop();
    }
}

[[noreturn]] void usage(const char* why) {
    std::fprintf(stderr,
                 "gdnav-test-netem: %s\nusage: gdnav-test-netem --queue N [--delay-ms D] [--jitter-ms J] "
                 "[--loss-pct L] [--reorder-pct R] [--seed S]\n",
                 why);
    std::exit(2);
}

double number(const char* name, const char* v, double lo, double hi) {
    char* end = nullptr;
    const double x = std::strtod(v, &end);
    if (!end || *end || !(x >= lo && x <= hi))
        usage((std::string(name) + " must be a number in [" + std::to_string(lo) + ", " + std::to_string(hi) +
               "], not '" + v + "'")
                  .c_str());
    return x;
}

Options parse(int argc, char** argv) {
    Options o;
    bool have_queue = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (i + 1 >= argc) usage(("missing value after " + a).c_str());
        const char* v = argv[++i];
        if (a == "--queue") {
            o.queue = static_cast<unsigned>(number("--queue", v, 0, 65535));
            have_queue = true;
        } else if (a == "--delay-ms") {
            o.delay_ms = number("--delay-ms", v, 0, 10000);
        } else if (a == "--jitter-ms") {
            o.jitter_ms = number("--jitter-ms", v, 0, 10000);
        } else if (a == "--loss-pct") {
            o.loss_pct = number("--loss-pct", v, 0, 100);
        } else if (a == "--reorder-pct") {
            o.reorder_pct = number("--reorder-pct", v, 0, 100);
        } else if (a == "--seed") {
            o.seed = static_cast<std::uint64_t>(number("--seed", v, 0, 1e15));
        } else {
            usage(("unknown option " + a).c_str());
        }
    }
    if (!have_queue) usage("--queue is required");
    return o;
}

}  // namespace

int main(int argc, char** argv) {
    State st;
    st.opt = parse(argc, argv);
    st.rng = gdnav::rnd::Stream::derive(st.opt.seed, 0, "gdnav-test-netem");
    signal(SIGTERM, on_signal);
    signal(SIGINT, on_signal);

    nfq_handle* h = nfq_open();
    if (!h) {
        std::fprintf(stderr, "gdnav-test-netem: nfq_open failed (%s): needs root and nfnetlink_queue\n",
                     std::strerror(errno));
        return 1;
    }
    st.qh = nfq_create_queue(h, static_cast<std::uint16_t>(st.opt.queue), &on_packet, &st);
    if (!st.qh) {
        std::fprintf(stderr, "gdnav-test-netem: cannot bind queue %u (%s)\n", st.opt.queue, std::strerror(errno));
        nfq_close(h);
        return 1;
    }
    nfq_set_mode(st.qh, NFQNL_COPY_META, 0);
    nfq_set_queue_maxlen(st.qh, 65536);
    const int fd = nfq_fd(h);
    int rcvbuf = 8 << 20;
    setsockopt(fd, SOL_SOCKET, SO_RCVBUFFORCE, &rcvbuf, sizeof(rcvbuf));
    std::fprintf(stderr, "gdnav-test-netem: queue %u, delay %.3g ms +- %.3g ms, loss %.3g %%, reorder %.3g %%\n",
                 st.opt.queue, st.opt.delay_ms, st.opt.jitter_ms, st.opt.loss_pct, st.opt.reorder_pct);

    alignas(8) static char buf[1 << 16];
    while (!g_stop) {
        std::int64_t wait_ns = 100'000'000;  // wake at least every 100 ms to see a signal
        if (!st.held.empty()) wait_ns = std::min<std::int64_t>(wait_ns, st.held.top().release_ns - now_ns());
        if (wait_ns < 0) wait_ns = 0;
        const timespec ts{static_cast<time_t>(wait_ns / 1000000000), static_cast<long>(wait_ns % 1000000000)};
        pollfd p{fd, POLLIN, 0};
        if (ppoll(&p, 1, &ts, nullptr) > 0 && (p.revents & POLLIN)) {
            for (;;) {
                const ssize_t n = recv(fd, buf, sizeof(buf), MSG_DONTWAIT);
                if (n <= 0) break;  // EAGAIN; ENOBUFS (kernel dropped some: counted as loss by DDS) — go on
                nfq_handle_packet(h, buf, static_cast<int>(n));
            }
        }
        release_due(st, now_ns());
    }
    release_due(st, INT64_MAX);
    nfq_destroy_queue(st.qh);
    nfq_close(h);
    std::fprintf(stderr, "gdnav-test-netem: %llu packets: %llu delayed, %llu released at once (reordered), %llu "
                         "dropped\n",
                 static_cast<unsigned long long>(st.packets), static_cast<unsigned long long>(st.delayed),
                 static_cast<unsigned long long>(st.reordered), static_cast<unsigned long long>(st.dropped));
    return 0;
}
