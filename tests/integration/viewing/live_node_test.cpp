// Issue 16 item 3: the live view. A Foxglove WebSocket client (@foxglove/ws-protocol, live_node/live_client.mjs)
// watches DISTRIBUTED scenario-#2 runs served by `gdnav run --live`:
//  * it connects during the run, subscribes to every advertised channel and decodes the messages with Foxglove's
//    OMG IDL deserializer from the advertised schemas; channels and schemas are the recording's; every field decoded
//    at several steps of every topic, and the bytes, equal the run's own recording (--record all, same run);
//  * a client that stops reading: the run completes, frames are dropped for it and counted (log and
//    <out>/live_stats.yaml);
//  * a bad port is one line and a non-zero exit before anything starts.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include "process_util.hpp"
#include "io/recording/record_file.hpp"
#include "framework/fields/field_table.hpp"
#include "framework/topic_types.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;
namespace fields = gdnav::framework::fields;
using nlohmann::json;

namespace {

constexpr std::uint64_t kStepNs = 10'000'000;  // scenario #2: dt = 0.01 s

std::string client_script() { return std::string(GDNAV_LIVE_NODE_DIR) + "/live_client.mjs"; }

// The value of field f of a decoded sample as the client writes it (JavaScript's String()).
bool same_value(const fields::Field& f, void* sample, std::size_t i, const std::string& got) {
    switch (f.kind) {
        case fields::Kind::F64: {
            const double want = static_cast<double*>(f.ptr(sample))[i];
            const double v = std::strtod(got.c_str(), nullptr);
            return std::isnan(want) ? std::isnan(v) : v == want;  // exact: JavaScript prints the shortest round trip
        }
        case fields::Kind::U64: return got == std::to_string(static_cast<std::uint64_t*>(f.ptr(sample))[i]);
        case fields::Kind::U32: return got == std::to_string(static_cast<std::uint32_t*>(f.ptr(sample))[i]);
        case fields::Kind::U8: return got == std::to_string(static_cast<std::uint8_t*>(f.ptr(sample))[i]);
        case fields::Kind::Bool: return got == (static_cast<bool*>(f.ptr(sample))[i] ? "true" : "false");
        case fields::Kind::Enum: return got == std::to_string(*static_cast<std::uint32_t*>(f.ptr(sample)));
        case fields::Kind::String: return got == f.get_str(sample);
    }
    return false;
}

std::string hex(const std::uint8_t* p, std::size_t n) {
    std::string s;
    char b[3];
    for (std::size_t i = 0; i < n; ++i) {
        std::snprintf(b, sizeof(b), "%02x", p[i]);
        s += b;
    }
    return s;
}

}  // namespace

TEST(LiveNode, ClientDuringDistributedRunDecodesTheRecordedValues) {
    gdnav::framework::register_gdnav_topics();
    const int port = free_port();
    ASSERT_GT(port, 0);
    const fs::path out = temp_dir("live-node");
    // Scenario #2, 3000 steps paced at 5x real time (6 s: time to connect), topics every 10th step (the default
    // decimation: the bridge reads the producers' decimated mirrors, dds/host/mirror.hpp), the recording of every
    // data topic in the same run.
    const pid_t run_pid = start({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--steps", "3000",
                                 "--layout", "distributed", "--realtime", "5", "--record", "all", "--live",
                                 std::to_string(port), "--live-decimation", "10", "--out", out.string()},
                                out.parent_path() / (out.filename().string() + ".run.log"));
    const fs::path client_json = out.parent_path() / (out.filename().string() + ".client.json");
    const Result client = run({GDNAV_NODE, client_script(), "ws://127.0.0.1:" + std::to_string(port),
                               client_json.string(), "read", "90"},
                              120.0);
    const int run_code = wait_for(run_pid, 120.0);
    const std::string run_log = read_file(out.parent_path() / (out.filename().string() + ".run.log"));
    ASSERT_EQ(run_code, 0) << run_log;
    std::printf("%s", client.output.c_str());
    ASSERT_EQ(client.exit_code, 0) << client.output << read_file(client_json);
    const json got = json::parse(read_file(client_json));
    EXPECT_TRUE(got.at("errors").empty()) << got.at("errors").dump();

    // The advertised channels are the recording's: every data topic (cdr, omgidl, the type, idl/gdnav.idl), plus
    // the viewer channels.
    std::set<std::string> topics;
    for (const auto& c : got.at("channels")) {
        const std::string topic = c.at("topic");
        topics.insert(topic);
        const gdnav::msg::MessageOps* ops = gdnav::framework::find_topic(topic);
        EXPECT_EQ(c.at("encoding"), "cdr") << topic;
        EXPECT_EQ(c.at("schemaEncoding"), "omgidl") << topic;
        if (!ops) {
            EXPECT_EQ(topic.rfind("/viewer/", 0), 0u) << "unexpected channel " << topic;
            continue;
        }
        EXPECT_EQ(c.at("schemaName"), ops->type_name) << topic;
        EXPECT_EQ(c.at("schema"), std::string(gdnav::framework::topic_schema_idl(topic))) << topic;
    }
    for (const auto& t : gdnav::framework::known_topics()) EXPECT_TRUE(topics.count(t)) << "not advertised: " << t;
    for (const char* v : {"/viewer/true/fix", "/viewer/est/fix", "/viewer/true/tf", "/viewer/est/tf", "/viewer/nav_errors",
                          "/viewer/true/pose", "/viewer/est/pose"})
        EXPECT_TRUE(topics.count(v)) << "not advertised: " << v;

    // Every data topic: messages at steps k % 10 == 0 only, log time = step * dt_ns, and at the sampled
    // steps every field (Foxglove's deserializer) and the bytes equal the recording's.
    const gdnav::io::recording::Recording rec = gdnav::io::recording::read_recording(out / "record");
    ASSERT_TRUE(rec.complete) << rec.problem;
    std::size_t compared_fields = 0;
    for (const auto& topic : gdnav::framework::known_topics()) {
        ASSERT_TRUE(got.at("topics").contains(topic)) << "no message of " << topic;
        const json& t = got.at("topics").at(topic);
        EXPECT_GT(t.at("count").get<int>(), 100) << topic;
        for (std::size_t i = 0; i < t.at("steps").size(); ++i) {
            const std::uint64_t step = t.at("steps")[i];
            EXPECT_EQ(step % 10, 0u) << topic << " step " << step;
            EXPECT_EQ(t.at("timestamps")[i].get<std::uint64_t>(), step * kStepNs) << topic << " step " << step;
            if (i > 0) {
                EXPECT_GT(step, t.at("steps")[i - 1].get<std::uint64_t>()) << topic;
            }
        }
        const gdnav::io::recording::TopicRecord& tr = rec.topics.at(topic);
        const fields::TypeFields* table = fields::find_type_fields(tr.ops->type_name);
        ASSERT_NE(table, nullptr) << tr.ops->type_name;
        gdnav::io::recording::SampleDecoder dec(*tr.ops);
        std::unique_ptr<void, void (*)(void*)> s(tr.ops->create(), tr.ops->destroy);
        int compared_steps = 0;
        for (const auto& [step_text, sample] : t.at("samples").items()) {
            const std::uint64_t step = std::stoull(step_text);
            auto e = std::find_if(tr.entries.begin(), tr.entries.end(), [&](const auto& x) { return x.step == step; });
            ASSERT_NE(e, tr.entries.end()) << topic << ": step " << step << " not in the recording";
            EXPECT_EQ(sample.at("hex").get<std::string>(), hex(&tr.bytes[e->offset], e->size)) << topic << " step " << step;
            ASSERT_TRUE(dec.decode(&tr.bytes[e->offset], e->size, s.get()));
            const json& f = sample.at("fields");
            for (std::size_t i = 0; i < table->count; ++i) {
                const fields::Field& fd = table->fields[i];
                ASSERT_TRUE(f.contains(fd.name)) << topic << ": field " << fd.name << " not decoded";
                const json& values = f.at(fd.name);
                const std::size_t n = fd.kind == fields::Kind::String || fd.kind == fields::Kind::Enum ? 1 : fd.count;
                ASSERT_EQ(values.size(), n) << topic << " " << fd.name;
                for (std::size_t k = 0; k < n; ++k) {
                    EXPECT_TRUE(same_value(fd, s.get(), k, values[k].get<std::string>()))
                        << topic << " step " << step << " " << fd.name << "[" << k << "]: live " << values[k];
                    ++compared_fields;
                }
            }
            ++compared_steps;
        }
        EXPECT_GE(compared_steps, 5) << topic;
    }
    std::printf("compared %zu decoded field values with the recording\n", compared_fields);

    // The viewer's true position is the recording's Truth, in degrees.
    const json& fix = got.at("topics").at("/viewer/true/fix");
    EXPECT_GT(fix.at("count").get<int>(), 50);
    const auto& truth = rec.topics.at("gdnav/Truth");
    gdnav::io::recording::SampleDecoder tdec(*truth.ops);
    std::unique_ptr<void, void (*)(void*)> ts(truth.ops->create(), truth.ops->destroy);
    const fields::TypeFields* ttable = fields::find_type_fields(truth.ops->type_name);
    int fixes = 0;
    for (const auto& [step_text, sample] : fix.at("samples").items()) {
        const std::uint64_t step = std::stoull(step_text);
        auto e = std::find_if(truth.entries.begin(), truth.entries.end(), [&](const auto& x) { return x.step == step; });
        ASSERT_NE(e, truth.entries.end());
        ASSERT_TRUE(tdec.decode(&truth.bytes[e->offset], e->size, ts.get()));
        double lat = NAN;
        for (std::size_t i = 0; i < ttable->count; ++i)
            if (std::string(ttable->fields[i].name) == "lat_rad") lat = *static_cast<double*>(ttable->fields[i].ptr(ts.get()));
        const double live_lat = std::strtod(sample.at("fields").at("latitude")[0].get<std::string>().c_str(), nullptr);
        EXPECT_NEAR(live_lat, lat * 180.0 / M_PI, 1e-9) << "step " << step;
        ++fixes;
    }
    EXPECT_GE(fixes, 5);

    // The bridge's statistics: one client, everything the client decoded was sent.
    const YAML::Node st = YAML::LoadFile((out / "live_stats.yaml").string());
    ASSERT_EQ(st["clients"].size(), 1u);
    EXPECT_GE(st["clients"][0]["messages_sent"].as<std::uint64_t>(), got.at("messages").get<std::uint64_t>());
    EXPECT_NE(run_log.find("frames sent"), std::string::npos);
    if (!::testing::Test::HasFailure()) {
        fs::remove_all(out);
        fs::remove(out.parent_path() / (out.filename().string() + ".run.log"));
        fs::remove(client_json);
    }
}

TEST(LiveNode, StalledClientCostsTheRunNothingAndItsFramesAreDroppedAndCounted) {
    const int port = free_port();
    ASSERT_GT(port, 0);
    const fs::path out = temp_dir("live-stall");
    const fs::path run_log_file = out.parent_path() / (out.filename().string() + ".run.log");
    const fs::path client_json = out.parent_path() / (out.filename().string() + ".client.json");
    // 10000 steps, every topic every step (~19 MB of messages) at 20x real time: far more than the socket buffers of
    // a client that reads nothing plus the bridge's 1 MiB per client. The bridge's process keeps its CPU priority
    // (run.observer_nice 0): at nice 19 on a loaded machine it gives up most steps (as an observer may), streams a
    // few hundred frames, and the client's buffers never fill.
    const pid_t run_pid = start({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--steps", "10000",
                                 "--layout", "distributed", "--realtime", "20", "--live", std::to_string(port),
                                 "--live-decimation", "1", "--set", "run.observer_nice=0", "--out", out.string()},
                                run_log_file);
    const pid_t client_pid = start({GDNAV_NODE, client_script(), "ws://127.0.0.1:" + std::to_string(port),
                                    client_json.string(), "stall", "300"},
                                   out.parent_path() / (out.filename().string() + ".client.log"));
    const int run_code = wait_for(run_pid, 200.0);
    const bool client_alive = wait_for(client_pid, 0) < 0;  // still idling, its socket paused
    kill(client_pid, SIGKILL);
    wait_for(client_pid, 10.0);
    const std::string run_log = read_file(run_log_file);
    ASSERT_EQ(run_code, 0) << run_log;
    EXPECT_TRUE(client_alive) << read_file(out.parent_path() / (out.filename().string() + ".client.log"));
    const json got = json::parse(read_file(client_json));
    ASSERT_TRUE(got.at("stalled").get<bool>()) << "the client never received a message";

    const YAML::Node summary = YAML::LoadFile((out / "clock_summary.yaml").string());
    EXPECT_TRUE(summary["completed"].as<bool>());
    EXPECT_EQ(summary["steps_done"].as<std::uint64_t>(), 10000u);
    const YAML::Node st = YAML::LoadFile((out / "live_stats.yaml").string());
    ASSERT_EQ(st["clients"].size(), 1u);
    const YAML::Node c = st["clients"][0];
    std::printf("stalled client: %llu frames sent, %llu dropped (%llu messages dropped); bridge queue drops %llu\n",
                static_cast<unsigned long long>(c["frames_sent"].as<std::uint64_t>()),
                static_cast<unsigned long long>(c["frames_dropped"].as<std::uint64_t>()),
                static_cast<unsigned long long>(c["messages_dropped"].as<std::uint64_t>()),
                static_cast<unsigned long long>(st["frames_dropped_queue"].as<std::uint64_t>()));
    EXPECT_GT(c["frames_dropped"].as<std::uint64_t>(), 0u);
    EXPECT_GT(c["messages_dropped"].as<std::uint64_t>(), 0u);
    EXPECT_GT(c["frames_sent"].as<std::uint64_t>(), 0u);
    // Sent + dropped = the steps the bridge streamed or skipped (every subscribed client stalled) after the client
    // subscribed: none is queued without bound.
    EXPECT_LE(c["frames_sent"].as<std::uint64_t>() + c["frames_dropped"].as<std::uint64_t>(),
              st["steps_streamed"].as<std::uint64_t>() + st["steps_skipped"].as<std::uint64_t>());
    EXPECT_GT(c["frames_sent"].as<std::uint64_t>() + c["frames_dropped"].as<std::uint64_t>(), 5000u);
    // Reported in the log at the end.
    const std::string line = "frames sent, " + c["frames_dropped"].as<std::string>() + " frames dropped";
    EXPECT_NE(run_log.find(line), std::string::npos) << run_log;
    if (!::testing::Test::HasFailure()) {
        fs::remove_all(out);
        fs::remove(run_log_file);
        fs::remove(client_json);
        fs::remove(out.parent_path() / (out.filename().string() + ".client.log"));
    }
}

TEST(LiveNode, BadPortIsOneLineAndNothingStarts) {
    const fs::path out = temp_dir("live-badport");
    const Result r = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--steps", "10", "--live", "70000", "--out",
                          out.string()},
                         60.0);
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("--live: port '70000' is not an integer in [1, 65535]"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out / "run.yaml"));

    // A port in use: the member's configuration (checked before any process starts) names the key.
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ASSERT_EQ(bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof(a)), 0);
    ASSERT_EQ(listen(fd, 1), 0);
    socklen_t n = sizeof(a);
    getsockname(fd, reinterpret_cast<sockaddr*>(&a), &n);
    const Result busy = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--steps", "10", "--live",
                             std::to_string(ntohs(a.sin_port)), "--out", out.string()},
                            60.0);
    close(fd);
    EXPECT_EQ(busy.exit_code, 2) << busy.output;
    EXPECT_NE(busy.output.find("components.live.port"), std::string::npos) << busy.output;
    EXPECT_NE(busy.output.find("in use"), std::string::npos) << busy.output;
    EXPECT_FALSE(fs::exists(out / "run.yaml"));
    if (!::testing::Test::HasFailure()) fs::remove_all(out);
}
