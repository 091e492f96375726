// gdnav-raw-member: a lockstep member written from docs/protocol.md alone, with nothing but the raw Fast DDS 2.9 DDS
// API and the fastddsgen types of idl/gdnav.idl and tests/chain/chain.idl (no gdnav runtime class or header). It
// replaces the test chain's `chain_controller` (tests/chain): input chain/estimate (Lag Same), output chain/control,
// u = -kp (x_hat - target) - kd v_hat. Section numbers (§) refer to docs/protocol.md.
//   gdnav-raw-member --domain D [--run I] [--name chain_controller] [--kp 1] [--kd 1.5] [--target 0]
//                    [--startup-timeout 120] [--protocol-version V]   (the last one only to test the refusal, §3.1)
//                    [--nan-t-at K]   (its sample of step K with t_s NaN: to test that consumers reject it, §3.5)
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <fastdds/dds/core/condition/WaitSet.hpp>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>

#include "chainPubSubTypes.h"
#include "gdnavPubSubTypes.h"

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::Duration_t;
namespace msg = gdnav::msg;
namespace chain = gdnav::testchain;

namespace {

volatile std::sig_atomic_t g_signal = 0;
double now_s() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// §2.3 QoS profiles, set in code: data = KEEP_LAST 32, control = KEEP_LAST 256 (both VOLATILE), latched = KEEP_LAST 8
// TRANSIENT_LOCAL; all RELIABLE, data sharing OFF; data writers publish synchronously.
enum class Profile { Data, Control, Latched };
template <class Qos> void set_qos(Qos& q, Profile p) {
    q.reliability().kind = RELIABLE_RELIABILITY_QOS;
    q.durability().kind = p == Profile::Latched ? TRANSIENT_LOCAL_DURABILITY_QOS : VOLATILE_DURABILITY_QOS;
    q.history().kind = KEEP_LAST_HISTORY_QOS;
    q.history().depth = p == Profile::Data ? 32 : p == Profile::Control ? 256 : 8;
    q.data_sharing().off();
}

struct Participant {
    DomainParticipant* dp{nullptr};
    Publisher* pub{nullptr};
    Subscriber* sub{nullptr};
    std::map<std::string, Topic*> topics;

    explicit Participant(int domain) {
        // §2.3: UDPv4 only, lease 75 s, announcement period 1 s; no XML profile is loaded.
        DomainParticipantQos pq = PARTICIPANT_QOS_DEFAULT;
        pq.name("gdnav-raw-member");
        pq.transport().use_builtin_transports = false;
        pq.transport().user_transports.push_back(std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>());
        pq.wire_protocol().builtin.discovery_config.leaseDuration = Duration_t(75, 0);
        pq.wire_protocol().builtin.discovery_config.leaseDuration_announcementperiod = Duration_t(1, 0);
        dp = DomainParticipantFactory::get_instance()->create_participant(domain, pq);
        if (!dp) throw std::runtime_error("cannot create a participant on domain " + std::to_string(domain));
        pub = dp->create_publisher(PUBLISHER_QOS_DEFAULT);
        sub = dp->create_subscriber(SUBSCRIBER_QOS_DEFAULT);
    }
    ~Participant() {
        dp->delete_contained_entities();
        DomainParticipantFactory::get_instance()->delete_participant(dp);
    }
    // §2, §11: topic name as given; DDS type name = the generated type's name (gdnav::msg::Tick, gdnav::testchain::...).
    template <class PubSubType> Topic* topic(const std::string& name) {
        auto& t = topics[name];
        if (t) return t;
        TypeSupport ts(new PubSubType());
        ts.register_type(dp);
        t = dp->create_topic(name, ts.get_type_name(), TOPIC_QOS_DEFAULT);
        return t;
    }
    template <class PubSubType> DataWriter* writer(const std::string& name, Profile p) {
        DataWriterQos q = DATAWRITER_QOS_DEFAULT;
        set_qos(q, p);
        q.publish_mode().kind = SYNCHRONOUS_PUBLISH_MODE;
        return pub->create_datawriter(topic<PubSubType>(name), q);
    }
    template <class PubSubType> DataReader* reader(const std::string& name, Profile p) {
        DataReaderQos q = DATAREADER_QOS_DEFAULT;
        set_qos(q, p);
        return sub->create_datareader(topic<PubSubType>(name), q);
    }
};

template <class T> bool take(DataReader* r, T& sample) {  // next valid sample
    SampleInfo info;
    while (r->take_next_sample(&sample, &info) == ReturnCode_t::RETCODE_OK)
        if (info.valid_data) return true;
    return false;
}

bool contains(const std::string& csv, const std::string& topic) {  // §3.1: comma-separated, no spaces
    std::size_t b = 0;
    while (b <= csv.size()) {
        std::size_t e = csv.find(',', b);
        if (e == std::string::npos) e = csv.size();
        if (csv.compare(b, e - b, topic) == 0 && e > b) return true;
        b = e + 1;
    }
    return false;
}

}  // namespace

int main(int argc, char** argv) {
    std::map<std::string, std::string> a{{"--domain", ""}, {"--run", "0"}, {"--name", "chain_controller"},
                                         {"--kp", "1.0"}, {"--kd", "1.5"}, {"--target", "0.0"},
                                         {"--startup-timeout", "120"}, {"--nan-t-at", ""},
                                         {"--protocol-version", std::to_string(gdnav::msg::LOCKSTEP_PROTOCOL_VERSION)}};
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!a.count(argv[i])) return std::fprintf(stderr, "unknown option %s\n", argv[i]), 2;
        a[argv[i]] = argv[i + 1];
    }
    if (a["--domain"].empty()) return std::fprintf(stderr, "usage: %s --domain D [options]\n", argv[0]), 2;
    const int domain = std::stoi(a["--domain"]);
    const std::uint64_t run = std::stoull(a["--run"]);
    const std::string name = a["--name"];
    const double kp = std::stod(a["--kp"]), kd = std::stod(a["--kd"]), target = std::stod(a["--target"]);
    const double startup_timeout_s = std::stod(a["--startup-timeout"]);
    const std::uint64_t nan_at = a["--nan-t-at"].empty() ? UINT64_MAX : std::stoull(a["--nan-t-at"]);
    const auto V = static_cast<std::uint32_t>(std::stoul(a["--protocol-version"]));  // LOCKSTEP_PROTOCOL_VERSION
    const std::string kIn = "chain/estimate", kOut = "chain/control";  // the member's declared input (Lag Same), output
    std::signal(SIGINT, [](int s) { g_signal = s; });
    std::signal(SIGTERM, [](int s) { g_signal = s; });

    char hn[256] = {};
    gethostname(hn, sizeof(hn) - 1);
    const std::string host = std::string(hn) + ":" + std::to_string(getpid());  // §3.1 host = hostname:pid

    // §2.1 control topics, §2.2 data topics: one reader per input, one writer per output.
    Participant p(domain);
    DataWriter* st_w = p.writer<msg::ComponentStatusPubSubType>("gdnav/ComponentStatus", Profile::Control);
    DataReader* st_r = p.reader<msg::ComponentStatusPubSubType>("gdnav/ComponentStatus", Profile::Control);
    DataReader* rc_r = p.reader<msg::RunControlPubSubType>("gdnav/RunControl", Profile::Latched);
    DataReader* tk_r = p.reader<msg::TickPubSubType>("gdnav/Tick", Profile::Control);
    DataWriter* dn_w = p.writer<msg::StepDonePubSubType>("gdnav/StepDone", Profile::Control);
    DataReader* in_r = p.reader<chain::ChainEstimatePubSubType>(kIn, Profile::Data);
    DataWriter* out_w = p.writer<chain::ChainControlPubSubType>(kOut, Profile::Data);
    if (!st_w || !st_r || !rc_r || !tk_r || !dn_w || !in_r || !out_w) return std::fprintf(stderr, "DDS setup failed\n"), 1;
    WaitSet ws;
    for (DataReader* r : {st_r, rc_r, tk_r, in_r}) {
        r->get_statuscondition().set_enabled_statuses(StatusMask::data_available());
        ws.attach_condition(r->get_statuscondition());
    }

    enum class State { Announce, Matching, Ready, Running } state = State::Announce;  // §3
    msg::RunControl cfg;                 // the CONFIGURE adopted (§3.2)
    std::uint64_t token = 0;             // its run token (§1): 0 until then
    std::uint32_t me = 0;                // my index in the member table
    std::vector<std::uint32_t> producers;  // table indices producing kIn
    int consumers = 0;                   // table entries reading kOut
    bool lost = false;                   // kIn lost (§3.5)
    std::uint64_t tick = 0, dead = 0, k = 0;
    std::map<std::uint64_t, chain::ChainEstimate> inbox;  // §3.5 inbox by stamp.step
    const double start = now_s();
    double last_clock = start, next_hb = start;

    auto status = [&](msg::StatusKind kind, const std::string& message) {  // §3.1
        msg::ComponentStatus s;
        const std::uint64_t done = k > 0 ? k - 1 : 0;
        s.run_id(run);
        s.step(done);
        s.t_s(state == State::Announce ? 0.0 : cfg.t0_s() + static_cast<double>(done) * cfg.dt_s());
        s.member(name);
        s.host(host);
        s.kind(kind);
        s.inputs(kIn);
        s.outputs(kOut);
        s.free_running(false);
        s.message(message);
        s.protocol_version(V);
        s.run_token(token);
        st_w->write(&s);
    };
    auto leave = [&](int code, const std::string& why) {  // §3.7, §5: exit codes; STATUS_EXIT before a non-zero exit
        if (code != 0) {
            std::fprintf(stderr, "%s: %s (exit %d)\n", name.c_str(), why.c_str(), code);
            status(msg::STATUS_EXIT, "exit code " + std::to_string(code));
            st_w->wait_for_acknowledgments(Duration_t(1, 0));
        } else {
            std::printf("%s: STOP received after %llu steps\n", name.c_str(), static_cast<unsigned long long>(k));
        }
        return code;
    };

    ConditionSeq active;
    msg::RunControl rc;
    msg::ComponentStatus st;
    msg::Tick tk;
    chain::ChainEstimate est;
    while (true) {
        ws.wait(active, Duration_t(0, 20'000'000));  // at most 20 ms: heartbeats and timeouts between samples
        const double now = now_s();
        if (g_signal) return leave(130, "stopped by signal " + std::to_string(g_signal));
        // §3.2, §3.7: RunControl of my run_id (and, once joined, of my token); STOP/ABORT in any state; the first
        // CONFIGURE only.
        while (take(rc_r, rc)) {
            if (rc.run_id() != run || (token != 0 && rc.run_token() != token)) continue;
            if (rc.command() == msg::RUN_STOP) return leave(0, "");
            if (rc.command() == msg::RUN_ABORT) return leave(3, "run aborted by the clock: " + rc.reason().to_string());
            if (rc.command() != msg::RUN_CONFIGURE || state != State::Announce) continue;
            if (rc.protocol_version() != V)
                return leave(5, "the clock speaks lockstep protocol version " + std::to_string(rc.protocol_version()) +
                                    ", this member speaks " + std::to_string(V));
            cfg = rc;
            token = rc.run_token();
            last_clock = now;  // §5: the lost-clock timer runs from CONFIGURE (heartbeats count once it has the token)
            bool found = false;
            for (std::uint32_t i = 0; i < cfg.members().size(); ++i) {
                const msg::MemberInfo& m = cfg.members()[i];
                if (m.name().to_string() == name) me = i, found = true;  // look the name up, never assume an order
                if (contains(m.outputs().to_string(), kIn)) producers.push_back(i);
                consumers += contains(m.inputs().to_string(), kOut);
            }
            if (!found) return leave(5, "'" + name + "' is not in the clock's member table");
            lost = producers.empty();  // an input without producer is lost from step 0
            state = State::Matching;
        }
        // §5 lost clock: a heartbeat of member `clock` of my run (and token) counts as a sign of life.
        while (take(st_r, st))
            if (st.run_id() == run && st.member().to_string() == "clock" && token != 0 && st.run_token() == token)
                last_clock = now;
        // §3.4: Ticks of my run (after CONFIGURE); tick_step = largest n; OR the dead_mask in.
        while (take(tk_r, tk)) {
            if (tk.stamp().run_id() != run || state == State::Announce || tk.run_token() != token) continue;
            last_clock = now;
            state = State::Running;
            tick = std::max(tick, tk.stamp().step());
            dead |= tk.dead_mask();
            bool all_dead = !producers.empty();
            for (std::uint32_t i : producers) all_dead = all_dead && ((dead >> i) & 1u);
            lost = lost || all_dead;
        }
        // §3.3 matching: readers by producers, writers by consumers, Tick reader and StepDone writer by the clock.
        if (state == State::Matching) {
            SubscriptionMatchedStatus rs, ts;
            PublicationMatchedStatus ws_out, ds;
            in_r->get_subscription_matched_status(rs);
            tk_r->get_subscription_matched_status(ts);
            out_w->get_publication_matched_status(ws_out);
            dn_w->get_publication_matched_status(ds);
            if (rs.current_count >= static_cast<int>(producers.size()) && ws_out.current_count >= consumers &&
                ts.current_count >= 1 && ds.current_count >= 1) {
                state = State::Ready;
                next_hb = now;  // READY at once
            }
        }
        // §3.1, §4: one status every 0.1 s wall; READY until the first Tick.
        if (now >= next_hb) {
            next_hb = now + 0.1;
            status(state == State::Ready ? msg::STATUS_READY : msg::STATUS_HEARTBEAT, "");
        }
        // §3.5: inbox by step; older samples than needed (Lag Same: < k) are dropped.
        while (take(in_r, est))
            if (est.stamp().run_id() == run && est.stamp().step() >= k) inbox[est.stamp().step()] = est;
        // §3.4 window, §3.5 binding, §3.6 outputs then StepDone.
        while (state == State::Running && k <= tick + cfg.window_steps() && k < cfg.steps()) {
            auto it = inbox.find(k);
            if (!lost && it == inbox.end()) break;  // wait for exactly step k's sample
            const chain::ChainEstimate* e = lost ? nullptr : &it->second;
            const double t_s = cfg.t0_s() + static_cast<double>(k) * cfg.dt_s();  // §3.2: k as double first
            chain::ChainControl out;
            // §7: the built-in controller's arithmetic, operation for operation (no FMA: -ffp-contract=off).
            out.u_mps2(e ? -kp * (e->x_m() - target) - kd * e->v_mps() : 0.0);  // lost estimate: no command
            out.stamp().run_id(run);
            out.stamp().step(k);
            out.stamp().t_s(k == nan_at ? std::numeric_limits<double>::quiet_NaN() : t_s);
            out_w->write(&out);
            if (e) inbox.erase(it);
            const std::uint64_t done_every = std::max<std::uint64_t>(cfg.done_every(), 1);
            if ((k + 1) % done_every == 0 || k + 1 == cfg.steps()) {
                msg::StepDone d;
                d.run_id(run);
                d.step(k);
                d.member_index(me);
                d.run_token(token);
                dn_w->write(&d);
            }
            ++k;
        }
        // §5 timeouts: no CONFIGURE within the start-up time (exit 5); after CONFIGURE, the clock silent (exit 4).
        if (state == State::Announce && now - start > startup_timeout_s)
            return leave(5, "no member table from the clock 'clock' within " + a["--startup-timeout"] + " s");
        if (state != State::Announce && now - last_clock > cfg.member_timeout_s())
            return leave(4, "lost the clock 'clock': no Tick or heartbeat for " + std::to_string(now - last_clock) + " s");
    }
}
