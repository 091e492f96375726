// A run owns its DDS domain (docs/protocol.md §1, docs/runtime.md "DDS domains"):
//  - a second run on the domain of a running one refuses with one line before any of its members starts, and the
//    first completes with the outputs of the same run alone;
//  - control messages of another run (another run token: a member's status and StepDone, a clock's heartbeat, Tick,
//    RunControl ABORT) are ignored and counted;
//  - a clock heard late (after kClaimListenS, while its run's members are already heard) is still refused; members
//    of an ended run (no clock) hold the domain no longer than kClaimLongestS;
//  - runs without --domain started together get different domains.
#include <gtest/gtest.h>
#include <signal.h>

#include <atomic>
#include <chrono>
#include <regex>
#include <thread>

#include <yaml-cpp/yaml.h>

#include "dds/dds_context.hpp"
#include "framework/lockstep.hpp"
#include "framework/run_config.hpp"
#include "framework/topic_types.hpp"
#include "msgs/messages.hpp"
#include "process_util.hpp"

using namespace gdnav::testing;
namespace msg = gdnav::msg;
namespace framework = gdnav::framework;
namespace fs = std::filesystem;

namespace {

// Domains of these tests (below the other integration tests' 120-232, above the launcher's first free ones).
constexpr int kSharedDomain = 111;
constexpr int kForeignDomain = 112;
constexpr int kLateClockDomain = 113;
constexpr int kEndedRunDomain = 114;

// The test chain, distributed, paced to 10x real time: 3000 steps = 30 s simulated, about 3 s of wall time.
std::vector<std::string> chain_run(const fs::path& out, const std::string& layout, int domain) {
    std::vector<std::string> a{testchain_exe(), "run",      "--scenario", chain_scenario(), "--layout", layout,
                               "--steps",       "3000",     "--realtime", "10",             "--out",    out.string()};
    if (domain >= 0) a.insert(a.end(), {"--domain", std::to_string(domain)});
    return a;
}

// Waits until the run logging to `log` has started step 0 (its clock took the domain and every member is ready).
bool wait_started(const fs::path& log, pid_t pid) {
    for (int i = 0; i < 600; ++i) {
        if (read_file(log).find("starts (") != std::string::npos) return true;
        if (wait_for(pid, 0.0) != -1) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
}

int finish(pid_t pid) {
    const int code = wait_for(pid, 120.0);
    if (code == -1) kill(pid, SIGINT);
    return code;
}

// Another run as the domain shows it to a starting clock: its member's heartbeats every 50 ms from the start and,
// from `clock_after` on (never when negative), its clock's heartbeat naming its output folder.
class OtherRun {
public:
    OtherRun(int domain, std::chrono::milliseconds clock_after)
        : dds_(domain, framework::config_dir() / "dds" / "gdnav_profiles.xml", "gdnav.test.other") {
        framework::register_gdnav_topics();
        writer_ = dds_.writer(gdnav::topics::kStatus, msg::message_ops<gdnav::msg::ComponentStatus>(),
                              gdnav::dds::kControlWriterProfile);
        thread_ = std::thread([this, clock_after] {
            const auto t0 = std::chrono::steady_clock::now();
            while (!stop_) {
                const bool clock = clock_after.count() >= 0 && std::chrono::steady_clock::now() - t0 >= clock_after;
                write("chain_plant", "");
                if (clock) write(framework::kClockName, "/elsewhere/other-run");
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
            }
        });
    }
    ~OtherRun() {
        stop_ = true;
        thread_.join();
    }
    OtherRun(const OtherRun&) = delete;
    OtherRun& operator=(const OtherRun&) = delete;

private:
    void write(const char* member, const char* message) {
        gdnav::msg::ComponentStatus s;
        s.run_id(7);
        s.member(member);
        s.host("other:1");
        s.kind(gdnav::msg::STATUS_HEARTBEAT);
        s.message(message);
        s.protocol_version(gdnav::msg::LOCKSTEP_PROTOCOL_VERSION);
        s.run_token(0x0ddba11c0ffee000ULL);
        s.step(1234);
        writer_->write(&s);
    }

    gdnav::dds::DdsContext dds_;
    eprosima::fastdds::dds::DataWriter* writer_{nullptr};
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

}  // namespace

TEST(Domain, AClockHeardAfterTheFirstSecondOfTheClaimIsStillRefused) {
    const fs::path dir = temp_dir("domain-late-clock");
    // The other run's clock is heard 2 s after this run's launcher starts, so after kClaimListenS of its clock's
    // claim (the clock starts after the launcher), while its member is heard from the start.
    static_assert(framework::kClaimListenS < 2.0 && 2.0 < framework::kClaimLongestS - 0.5);
    const OtherRun other(kLateClockDomain, std::chrono::milliseconds(2000));
    const Result b = run(chain_run(dir / "B", "composed", kLateClockDomain), 60.0);
    EXPECT_EQ(b.exit_code, framework::kExitStartup) << b.output;
    EXPECT_EQ(count_of(b.output, "is in use by another run"), 1u) << b.output;
    EXPECT_NE(b.output.find("output /elsewhere/other-run"), std::string::npos) << b.output;
    EXPECT_FALSE(fs::exists(dir / "B" / "processes.yaml")) << "members were started: " << b.output;
}

TEST(Domain, MembersOfARunWhoseClockIsGoneDoNotHoldTheDomain) {
    const fs::path dir = temp_dir("domain-ended-run");
    const OtherRun other(kEndedRunDomain, std::chrono::milliseconds(-1));
    const Result b = run(chain_run(dir / "B", "composed", kEndedRunDomain), 60.0);
    ASSERT_EQ(b.exit_code, 0) << b.output;
    EXPECT_EQ(count_of(b.output, "but not its clock (a run that ended)"), 1u) << b.output;
    EXPECT_TRUE(YAML::LoadFile((dir / "B" / "clock_summary.yaml").string())["completed"].as<bool>());
}

TEST(Domain, SecondRunOnADomainRefusesBeforeItsMembersStartFirstRunUnchanged) {
    const fs::path dir = temp_dir("domain-shared");
    const fs::path a_out = dir / "A", b_out = dir / "B", alone_out = dir / "alone";
    const pid_t a = start(chain_run(a_out, "distributed", kSharedDomain), dir / "A.log");
    ASSERT_TRUE(wait_started(dir / "A.log", a)) << read_file(dir / "A.log");
    const Result b = run(chain_run(b_out, "composed", kSharedDomain), 60.0);
    const int a_code = finish(a);
    const std::string a_log = read_file(dir / "A.log");

    EXPECT_EQ(b.exit_code, framework::kExitStartup) << b.output;
    EXPECT_EQ(count_of(b.output, "is in use by another run"), 1u) << b.output;
    EXPECT_EQ(count_of(b.output, "] error: "), 1u) << "one line, not more: " << b.output;
    EXPECT_NE(b.output.find("output " + a_out.string()), std::string::npos) << "names the other run: " << b.output;
    EXPECT_FALSE(fs::exists(b_out / "processes.yaml")) << "members were started: " << b.output;

    ASSERT_EQ(a_code, 0) << a_log;
    const Result alone = run(chain_run(alone_out, "distributed", -1), 120.0);
    ASSERT_EQ(alone.exit_code, 0) << alone.output;
    const auto digests = read_digests(a_out);
    EXPECT_EQ(digests.size(), 4u) << a_log;
    EXPECT_EQ(digests, read_digests(alone_out)) << "the run that kept its domain changed: " << a_log;
}

TEST(Domain, ControlMessagesOfAnotherRunAreIgnoredAndCounted) {
    const fs::path dir = temp_dir("domain-foreign");
    const fs::path out = dir / "run", direct_out = dir / "direct";
    const pid_t launcher = start(chain_run(out, "distributed", kForeignDomain), dir / "run.log");
    ASSERT_TRUE(wait_started(dir / "run.log", launcher)) << read_file(dir / "run.log");

    // Another run's participant: the statuses of a member that gives up and of a clock, StepDone far ahead for
    // every table index, a last Tick and an ABORT, all with its own token, every 20 ms for 1.5 s once its writers
    // reach the run (a sample written before is lost).
    framework::register_gdnav_topics();
    std::uint64_t sent = 0, to_clock = 0;
    {
        gdnav::dds::DdsContext dds(kForeignDomain, framework::config_dir() / "dds" / "gdnav_profiles.xml",
                                   "gdnav.test.foreign");
        using gdnav::msg::ComponentStatus;
        auto* status_w = dds.writer(gdnav::topics::kStatus, msg::message_ops<ComponentStatus>(),
                                    gdnav::dds::kControlWriterProfile);
        auto* done_w = dds.writer(gdnav::topics::kStepDone, msg::message_ops<gdnav::msg::StepDone>(),
                                  gdnav::dds::kControlWriterProfile);
        auto* tick_w =
            dds.writer(gdnav::topics::kTick, msg::message_ops<gdnav::msg::Tick>(), gdnav::dds::kControlWriterProfile);
        auto* control_w = dds.writer(gdnav::topics::kRunControl, msg::message_ops<gdnav::msg::RunControl>(),
                                     gdnav::dds::kLatchedWriterProfile);
        constexpr std::uint64_t kToken = 0x0bad0bad0bad0badULL;
        const auto matched = [](eprosima::fastdds::dds::DataWriter* w) {
            eprosima::fastdds::dds::PublicationMatchedStatus st;
            w->get_publication_matched_status(st);
            return st.current_count > 0;
        };
        for (int i = 0; i < 200 && !(matched(status_w) && matched(done_w) && matched(tick_w)); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(1500);
        while (std::chrono::steady_clock::now() < end && wait_for(launcher, 0.0) == -1) {
            for (const char* name : {"chain_plant", framework::kClockName}) {
                ComponentStatus s;
                s.run_id(0);
                s.member(name);
                s.host("foreign:1");
                s.kind(name == framework::kClockName ? gdnav::msg::STATUS_HEARTBEAT : gdnav::msg::STATUS_EXIT);
                s.message("exit code 4");
                s.protocol_version(gdnav::msg::LOCKSTEP_PROTOCOL_VERSION);
                s.run_token(kToken);
                status_w->write(&s);
            }
            for (std::uint32_t i = 0; i < 5; ++i) {
                gdnav::msg::StepDone d;
                d.step(1000000);
                d.member_index(i);
                d.run_token(kToken);
                done_w->write(&d);
            }
            gdnav::msg::Tick t;
            t.stamp().step(1000000);
            t.dead_mask(~0ULL);
            t.last(true);
            t.run_token(kToken);
            tick_w->write(&t);
            gdnav::msg::RunControl c;
            c.command(gdnav::msg::RUN_ABORT);
            c.reason("foreign abort");
            c.run_token(kToken);
            control_w->write(&c);
            sent += 9;
            to_clock += 7;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        for (auto* w : {status_w, done_w}) w->wait_for_acknowledgments(eprosima::fastrtps::Duration_t(2, 0));
    }
    const int code = finish(launcher);
    const std::string log = read_file(dir / "run.log");
    ASSERT_EQ(code, 0) << log;
    ASSERT_GT(sent, 100u);
    EXPECT_EQ(log.find("foreign abort"), std::string::npos) << log;

    // Counted: the clock ignored the statuses and StepDones sent to it ...
    const YAML::Node summary = YAML::LoadFile((out / "clock_summary.yaml").string());
    const auto ignored = summary["foreign_control_messages"].as<std::uint64_t>();
    std::printf("sent %llu foreign control messages (%llu to the clock); the clock ignored %llu\n",
                static_cast<unsigned long long>(sent), static_cast<unsigned long long>(to_clock),
                static_cast<unsigned long long>(ignored));
    EXPECT_GE(ignored, to_clock / 2);
    EXPECT_TRUE(summary["completed"].as<bool>());
    EXPECT_TRUE(summary["reproducible"].as<bool>()) << "nobody was declared dead";
    // ... logged once per source: the clock 3 sources, each of the 5 member processes 3 (RunControl, Tick, clock).
    const std::size_t lines = count_of(log, "ignoring control messages of another run");
    EXPECT_GE(lines, 3u) << log;
    EXPECT_LE(lines, 18u) << log;
    // Nothing changed: the same outputs as the run in one thread.
    const Result direct = run(chain_run(direct_out, "direct", -1), 120.0);
    ASSERT_EQ(direct.exit_code, 0) << direct.output;
    EXPECT_EQ(read_digests(out).size(), 4u);
    EXPECT_EQ(read_digests(out), read_digests(direct_out)) << log;
}

TEST(Domain, RunsWithoutADomainStartedTogetherGetDifferentOnes) {
    const fs::path dir = temp_dir("domain-auto");
    const pid_t one = start(chain_run(dir / "one", "composed", -1), dir / "one.log");
    const pid_t two = start(chain_run(dir / "two", "composed", -1), dir / "two.log");
    EXPECT_EQ(finish(one), 0) << read_file(dir / "one.log");
    EXPECT_EQ(finish(two), 0) << read_file(dir / "two.log");
    const std::regex printed(R"(DDS domain (\d+) \(no other run of this host uses it)");
    std::smatch m1, m2;
    const std::string log1 = read_file(dir / "one.log"), log2 = read_file(dir / "two.log");
    ASSERT_TRUE(std::regex_search(log1, m1, printed)) << log1;
    ASSERT_TRUE(std::regex_search(log2, m2, printed)) << log2;
    EXPECT_NE(m1[1].str(), m2[1].str());
    // Each run's members were given its domain.
    for (const auto& [name, m] : {std::pair{"one", m1[1].str()}, std::pair{"two", m2[1].str()}})
        EXPECT_EQ(YAML::LoadFile((dir / name / "run.yaml").string())["run"]["domain_id"].as<std::string>(), m)
            << name;
}
