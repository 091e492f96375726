// A plain two-process Fast DDS ping-pong with the messages an attitude member exchanges per step: the floor against
// which a process member's per-step cost in a gdnav run is judged (docs/runtime.md, "Members: what a step costs").
// No gdnav code: one participant per process, blocking on a WaitSet; by default Fast DDS's default transports (shared
// memory and UDP on one host, data sharing where the type allows it) and RELIABLE KEEP_LAST(1) readers and writers;
// with --profiles FILE the participant, writers and readers of gdnav's XML profiles instead (gdnav_participant,
// gdnav_data_writer, gdnav_data_reader: config/dds/gdnav_profiles.xml is UDP only, no data sharing), so that the floor
// is measured on the transport a gdnav run uses (docs/runtime.md, "Members: what a step costs"). Per round the "ping"
// process writes ImuSample, MagSample, AirDataEstimate and PositionEstimate stamped with the round; the "pong" process
// waits until it holds all four of that round and answers with an AttitudeEstimate; the ping waits for the answer.
// The round trip is the wall time from the first write to the answer's arrival.
//   bench_dds_ping_pong [--domain D (default 231)] [--rounds N (default 20000)] [--warmup N (default 1000)]
//                       [--profiles FILE]
// Prints the median, mean, 10th and 90th percentiles of the round trip in microseconds.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include <fastdds/dds/core/condition/WaitSet.hpp>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>

#include "gdnavPubSubTypes.h"

namespace fdds = eprosima::fastdds::dds;
namespace msg = gdnav::msg;

namespace {

// --profiles: the XML file whose gdnav profiles the endpoints use (empty: Fast DDS's defaults).
std::string g_profiles;

struct Endpoint {
    fdds::DomainParticipant* participant{nullptr};
    fdds::Publisher* publisher{nullptr};
    fdds::Subscriber* subscriber{nullptr};

    explicit Endpoint(int domain) {
        auto* factory = fdds::DomainParticipantFactory::get_instance();
        fdds::DomainParticipantQos pq = fdds::PARTICIPANT_QOS_DEFAULT;
        if (!g_profiles.empty() &&
            (factory->load_XML_profiles_file(g_profiles) != ReturnCode_t::RETCODE_OK ||
             factory->get_participant_qos_from_profile("gdnav_participant", pq) != ReturnCode_t::RETCODE_OK)) {
            std::fprintf(stderr, "bench_dds_ping_pong: %s: cannot load it or its profile 'gdnav_participant'\n",
                         g_profiles.c_str());
            std::exit(2);
        }
        participant = factory->create_participant(static_cast<fdds::DomainId_t>(domain), pq);
        if (participant == nullptr) {
            std::fprintf(stderr, "bench_dds_ping_pong: cannot create a participant on domain %d\n", domain);
            std::exit(2);
        }
        publisher = participant->create_publisher(fdds::PUBLISHER_QOS_DEFAULT);
        subscriber = participant->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
    }
    ~Endpoint() {
        participant->delete_contained_entities();
        fdds::DomainParticipantFactory::get_instance()->delete_participant(participant);
    }

    template <class PubSub>
    fdds::Topic* topic(const std::string& name) {
        fdds::TypeSupport type(new PubSub());
        type.register_type(participant);
        return participant->create_topic(name, type.get_type_name(), fdds::TOPIC_QOS_DEFAULT);
    }
    // RELIABLE, KEEP_LAST(1): each round's sample replaces the previous one, and none is lost.
    template <class Qos>
    static Qos reliable_last(Qos q) {
        q.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
        q.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
        q.history().depth = 1;
        return q;
    }
    template <class PubSub>
    fdds::DataWriter* writer(const std::string& name) {
        if (!g_profiles.empty())
            return publisher->create_datawriter_with_profile(topic<PubSub>(name), "gdnav_data_writer");
        return publisher->create_datawriter(topic<PubSub>(name), reliable_last(fdds::DATAWRITER_QOS_DEFAULT));
    }
    template <class PubSub>
    fdds::DataReader* reader(const std::string& name) {
        if (!g_profiles.empty())
            return subscriber->create_datareader_with_profile(topic<PubSub>(name), "gdnav_data_reader");
        return subscriber->create_datareader(topic<PubSub>(name), reliable_last(fdds::DATAREADER_QOS_DEFAULT));
    }
};

void wait_matched(fdds::DataWriter* w, fdds::DataReader* r) {
    for (;;) {
        fdds::PublicationMatchedStatus pm;
        fdds::SubscriptionMatchedStatus sm;
        if (w != nullptr) w->get_publication_matched_status(pm);
        if (r != nullptr) r->get_subscription_matched_status(sm);
        if ((w == nullptr || pm.current_count > 0) && (r == nullptr || sm.current_count > 0)) return;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
}

// Takes every sample of `r`; returns the largest step stamped on them (or `have` when none).
template <class T>
std::uint64_t take_newest(fdds::DataReader* r, std::uint64_t have) {
    T sample;
    fdds::SampleInfo info;
    while (r->take_next_sample(&sample, &info) == ReturnCode_t::RETCODE_OK) {
        if (info.valid_data) have = std::max(have, sample.stamp().step() + 1);
    }
    return have;
}

int pong(int domain, std::uint64_t rounds) {
    Endpoint e(domain);
    auto* imu = e.reader<msg::ImuSamplePubSubType>("bench/ImuSample");
    auto* mag = e.reader<msg::MagSamplePubSubType>("bench/MagSample");
    auto* air = e.reader<msg::AirDataEstimatePubSubType>("bench/AirDataEstimate");
    auto* pos = e.reader<msg::PositionEstimatePubSubType>("bench/PositionEstimate");
    auto* att = e.writer<msg::AttitudeEstimatePubSubType>("bench/AttitudeEstimate");
    fdds::WaitSet ws;
    for (auto* r : {imu, mag, air, pos}) {
        r->get_statuscondition().set_enabled_statuses(fdds::StatusMask::data_available());
        ws.attach_condition(r->get_statuscondition());
    }
    wait_matched(att, nullptr);
    // "have" counts steps: have_x = s + 1 once the sample of step s has arrived.
    std::uint64_t hi = 0, hm = 0, ha = 0, hp = 0;
    msg::AttitudeEstimate out;
    for (std::uint64_t s = 0; s < rounds; ++s) {
        while (std::min({hi, hm, ha, hp}) <= s) {
            fdds::ConditionSeq active;
            ws.wait(active, eprosima::fastrtps::Duration_t(5, 0));
            hi = take_newest<msg::ImuSample>(imu, hi);
            hm = take_newest<msg::MagSample>(mag, hm);
            ha = take_newest<msg::AirDataEstimate>(air, ha);
            hp = take_newest<msg::PositionEstimate>(pos, hp);
            if (getppid() == 1) return 1;  // the ping process is gone
        }
        out.stamp().step(s);
        att->write(&out);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(200));  // let the last answer be acknowledged
    return 0;
}

int ping(int domain, std::uint64_t rounds, std::uint64_t warmup) {
    Endpoint e(domain);
    auto* imu = e.writer<msg::ImuSamplePubSubType>("bench/ImuSample");
    auto* mag = e.writer<msg::MagSamplePubSubType>("bench/MagSample");
    auto* air = e.writer<msg::AirDataEstimatePubSubType>("bench/AirDataEstimate");
    auto* pos = e.writer<msg::PositionEstimatePubSubType>("bench/PositionEstimate");
    auto* att = e.reader<msg::AttitudeEstimatePubSubType>("bench/AttitudeEstimate");
    fdds::WaitSet ws;
    att->get_statuscondition().set_enabled_statuses(fdds::StatusMask::data_available());
    ws.attach_condition(att->get_statuscondition());
    for (auto* w : {imu, mag, air, pos}) wait_matched(w, nullptr);
    wait_matched(nullptr, att);
    msg::ImuSample i;
    msg::MagSample m;
    msg::AirDataEstimate a;
    msg::PositionEstimate p;
    std::vector<double> rtt_us;
    rtt_us.reserve(rounds);
    std::uint64_t have = 0;
    for (std::uint64_t s = 0; s < rounds; ++s) {
        const auto t0 = std::chrono::steady_clock::now();
        i.stamp().step(s);
        m.stamp().step(s);
        a.stamp().step(s);
        p.stamp().step(s);
        // A sample written while the other side is still completing discovery is delivered once it has; until an
        // answer comes the round is written again each second (the pong keeps the newest step it holds), 5 times.
        for (int attempt = 0; have <= s; ++attempt) {
            if (attempt == 5) {
                std::fprintf(stderr, "bench_dds_ping_pong: no answer to round %llu within 5 s\n",
                             static_cast<unsigned long long>(s));
                return 1;
            }
            imu->write(&i);
            mag->write(&m);
            air->write(&a);
            pos->write(&p);
            const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(1);
            while (have <= s && std::chrono::steady_clock::now() < deadline) {
                fdds::ConditionSeq active;
                ws.wait(active, eprosima::fastrtps::Duration_t(0, 100000000));
                have = take_newest<msg::AttitudeEstimate>(att, have);
            }
        }
        const std::chrono::duration<double, std::micro> dt = std::chrono::steady_clock::now() - t0;
        if (s >= warmup) rtt_us.push_back(dt.count());
    }
    std::sort(rtt_us.begin(), rtt_us.end());
    double sum = 0.0;
    for (double v : rtt_us) sum += v;
    const auto pct = [&](double q) { return rtt_us[static_cast<std::size_t>(q * (rtt_us.size() - 1))]; };
    std::printf("bench_dds_ping_pong: %zu round trips (after %llu warm-up) of ImuSample + MagSample + "
                "AirDataEstimate + PositionEstimate -> AttitudeEstimate between two processes, domain %d, %s\n",
                rtt_us.size(), static_cast<unsigned long long>(warmup), domain,
                g_profiles.empty() ? "Fast DDS's default transports and QoS" : ("profiles of " + g_profiles).c_str());
    std::printf("  round trip [us]: median %.1f, mean %.1f, p10 %.1f, p90 %.1f\n", pct(0.5), sum / rtt_us.size(),
                pct(0.1), pct(0.9));
    return 0;
}

std::uint64_t parse_count(const char* flag, const char* text, std::uint64_t lo, std::uint64_t hi) {
    char* end = nullptr;
    const unsigned long long v = std::strtoull(text, &end, 10);
    if (end == text || *end != '\0' || v < lo || v > hi) {
        std::fprintf(stderr, "bench_dds_ping_pong: %s must be an integer in [%llu, %llu], got '%s'\n", flag,
                     static_cast<unsigned long long>(lo), static_cast<unsigned long long>(hi), text);
        std::exit(2);
    }
    return v;
}

}  // namespace

int main(int argc, char** argv) {
    int domain = 231;
    std::uint64_t rounds = 20000, warmup = 1000;
    for (int a = 1; a < argc; ++a) {
        const std::string f = argv[a];
        if (a + 1 >= argc || (f != "--domain" && f != "--rounds" && f != "--warmup" && f != "--profiles")) {
            std::fprintf(stderr,
                         "usage: bench_dds_ping_pong [--domain D] [--rounds N] [--warmup N] [--profiles FILE]\n");
            return 2;
        }
        const char* v = argv[++a];
        if (f == "--profiles") g_profiles = v;
        if (f == "--domain") domain = static_cast<int>(parse_count("--domain", v, 0, 232));
        if (f == "--rounds") rounds = parse_count("--rounds", v, 1, 100000000);
        if (f == "--warmup") warmup = parse_count("--warmup", v, 0, 100000000);
    }
    if (warmup >= rounds) {
        std::fprintf(stderr, "bench_dds_ping_pong: --warmup (%llu) must be below --rounds (%llu)\n",
                     static_cast<unsigned long long>(warmup), static_cast<unsigned long long>(rounds));
        return 2;
    }
    const pid_t child = fork();
    if (child < 0) {
        std::perror("bench_dds_ping_pong: fork");
        return 2;
    }
    if (child == 0) _exit(pong(domain, rounds));
    const int rc = ping(domain, rounds, warmup);
    if (rc != 0) kill(child, SIGTERM);  // the pong would wait for rounds that never come
    int status = 0;
    waitpid(child, &status, 0);
    return rc != 0 ? rc : (WIFEXITED(status) ? WEXITSTATUS(status) : 1);
}
