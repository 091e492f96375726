#include "launch/run_rewrites.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include <spdlog/spdlog.h>

#include "io/recording/record_file.hpp"
#include "msgs/messages.hpp"
#include "framework/topic_types.hpp"
#include "io/viewer/viewer_channels.hpp"

namespace gdnav::launch {

namespace fs = std::filesystem;
using framework::RunConfig;

namespace {

constexpr const char* kRecorderName = "recorder";
constexpr const char* kReplayName = "replay";

[[noreturn]] void fail(const std::string& option, const std::string& what) {
    throw config::ConfigError("config error: " + option + ": " + what);
}

std::string join(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
    return s;
}

// The topics of `--record default`: the five sensor topics, i.e. a flight log (what `gdnav run --replay` needs to run
// the filters, and what export-log/import-log carry). Truth, the estimates, guidance and control are added by name.
const std::vector<std::string> kDefaultRecorded{"gdnav/ImuSample", "gdnav/MagSample", "gdnav/AirSample",
                                                "gdnav/AtmSample", "gdnav/GnssSample"};

// Full topic names, in the given order without repeats; "all" (alone) = every known data topic; "default" (with
// others or alone) = kDefaultRecorded.
std::vector<std::string> resolve_topics(const std::vector<std::string>& names, const std::string& option,
                                        bool allow_all) {
    if (allow_all && names.size() == 1 && names.front() == "all") return framework::known_topics();
    std::vector<std::string> out;
    for (const auto& n : names) {
        if (n == "all") fail(option, allow_all ? "'all' must be given alone" : "'all' is not allowed here");
        if (n == "default" && allow_all) {
            for (const auto& t : kDefaultRecorded)
                if (std::find(out.begin(), out.end(), t) == out.end()) out.push_back(t);
            continue;
        }
        const std::string t = io::recording::resolve_topic(n);
        if (t.empty()) fail(option, "unknown topic '" + n + "' (known: " + io::recording::known_topics_list() + ")");
        if (std::find(out.begin(), out.end(), t) == out.end()) out.push_back(t);
    }
    if (out.empty()) fail(option, "no topic given");
    return out;
}

YAML::Node sequence(const std::vector<std::string>& v) {
    YAML::Node s(YAML::NodeType::Sequence);
    for (const auto& x : v) s.push_back(x);
    return s;
}


// `viewer` in --record: the recorder's viewer channels (common/io/viewer; docs/viewing.md), with or without topics.
constexpr const char* kViewerKeyword = "viewer";

// The names without `viewer`, and whether it was among them.
std::pair<std::vector<std::string>, bool> split_viewer(const std::vector<std::string>& all_names) {
    std::vector<std::string> names;
    for (const auto& n : all_names)
        if (n != kViewerKeyword) names.push_back(n);
    const bool viewer = names.size() != all_names.size();
    return {std::move(names), viewer};
}

void add_recorder(YAML::Node comps, const std::vector<std::string>& all_names) {
    const auto [names, viewer] = split_viewer(all_names);
    const std::vector<std::string> topics =
        viewer && names.empty() ? std::vector<std::string>{} : resolve_topics(names, "--record", true);
    if (comps[kRecorderName]) {
        const YAML::Node type = comps[kRecorderName]["type"];
        if (!type || type.as<std::string>() != "recorder")
            fail("--record", std::string("the run already has a member named '") + kRecorderName +
                                 "' that is not a recorder");
        spdlog::info("--record: the run's member '{}' now records {}{}", kRecorderName, join(topics),
                     viewer ? (topics.empty() ? "the viewer channels" : " and the viewer channels") : "");
    } else {
        spdlog::info("--record: member '{}' records {}{}", kRecorderName, join(topics),
                     viewer ? (topics.empty() ? "the viewer channels" : " and the viewer channels") : "");
    }
    YAML::Node r(YAML::NodeType::Map);
    r["type"] = "recorder";
    r["topics"] = sequence(topics);
    if (viewer) r["viewer"] = true;
    comps[kRecorderName] = r;
}

void add_replay(YAML::Node root, const RunConfig& rc, const RunRewrites& rw, const framework::ComponentRegistry& reg) {
    if (rw.replay_topics.empty()) fail("--topics", "--replay needs the topics to replay (--topics ImuSample,MagSample,...)");
    const std::vector<std::string> topics = resolve_topics(rw.replay_topics, "--topics", false);
    std::error_code ec;
    const fs::path run_dir = fs::absolute(rw.replay_dir);
    const fs::path record_dir = run_dir / "record";
    if (!fs::is_directory(run_dir, ec)) fail("--replay", "'" + rw.replay_dir + "' is not a directory");
    std::vector<std::string> recorded;
    try {
        recorded = io::recording::recorded_topics(record_dir);
    } catch (const std::runtime_error& e) {
        fail("--replay", e.what());
    }
    for (const auto& t : topics)
        if (std::find(recorded.begin(), recorded.end(), t) == recorded.end())
            fail("--replay", io::recording::recording_file(record_dir).string() + ": no record of " + t +
                                 " (recorded there: " + (recorded.empty() ? std::string("nothing") : join(recorded)) +
                                 ")");
    if (fs::weakly_canonical(fs::absolute(rc.out_dir), ec) == fs::weakly_canonical(run_dir, ec))
        fail("--out", "the output directory is the replayed run directory " + run_dir.string() +
                          " (its records would be overwritten): give another --out");

    // Members whose outputs are all replayed are replaced; one that writes replayed and other topics cannot be.
    const std::set<std::string> replayed(topics.begin(), topics.end());
    std::vector<std::string> removed;
    for (const auto& c : rc.build(reg)) {
        std::vector<std::string> in, out;
        for (const auto* o : c->outputs()) (replayed.count(o->topic()) ? in : out).push_back(o->topic());
        if (in.empty()) continue;
        if (!out.empty())
            fail("--topics", "member '" + c->name() + "' writes " + join(in) + " (replayed) and " + join(out) +
                                 " (not replayed): replay all of its outputs or none");
        removed.push_back(c->name());
    }
    YAML::Node comps = root["components"];
    if (comps[kReplayName] && std::find(removed.begin(), removed.end(), kReplayName) == removed.end())
        fail("--replay", std::string("the run already has a member named '") + kReplayName + "'");
    for (const auto& n : removed) comps.remove(n);
    YAML::Node r(YAML::NodeType::Map);
    r["type"] = "replay";
    r["record"] = record_dir.string();
    r["topics"] = sequence(topics);
    comps[kReplayName] = r;

    // The replay is the run's data source: essential. Replaced members leave the essential list.
    std::vector<std::string> essential;
    for (const auto& e : rc.essential)
        if (std::find(removed.begin(), removed.end(), e) == removed.end()) essential.push_back(e);
    essential.push_back(kReplayName);
    root["run"]["essential"] = sequence(essential);
    // A fresh DDS domain (the launcher picks one) rather than the recorded run's, unless this run chose one.
    if (!rw.keep_domain) root["run"].remove("domain_id");
    // Without a replayed Truth the physics flies its own trajectory, which is no reference for recorded sensors:
    // the navigation recorders score nothing (docs/replay.md).
    if (!replayed.count(topics::kTruth))
        for (auto it = comps.begin(); it != comps.end(); ++it)
            if (it->second["type"] && it->second["type"].as<std::string>() == "nav_recorder")
                it->second["reference"] = "none";
    if (removed.empty())
        spdlog::info("--replay: {} from {} (no member of the run produced them)", join(topics), record_dir.string());
    else
        spdlog::info("--replay: {} from {} replace member(s) {}", join(topics), record_dir.string(), join(removed));
}

constexpr const char* kLiveName = "live";

// --live [PORT] (+ --live-bind, --live-decimation, --live-topics): a `live` member (components/live/live_bridge.hpp).
void add_live(YAML::Node comps, const RunConfig& rc, const RunRewrites& rw, const framework::ComponentRegistry& reg) {
    if (!rw.live) {
        for (const auto& [given, opt] : {std::pair{!rw.live_bind.empty(), "--live-bind"},
                                         std::pair{rw.live_decimation > 0, "--live-decimation"},
                                         std::pair{!rw.live_topics.empty(), "--live-topics"}})
            if (given) fail(opt, "needs --live [PORT]");
        return;
    }
    if (comps[kLiveName]) fail("--live", std::string("the run already has a member named '") + kLiveName + "'");
    YAML::Node l(YAML::NodeType::Map);
    l["type"] = "live";
    if (!rw.live_port.empty()) {
        const std::string& p = rw.live_port;
        const bool digits = p.size() <= 5 && p.find_first_not_of("0123456789") == std::string::npos;
        if (!digits || std::stoul(p) < 1 || std::stoul(p) > 65535)
            fail("--live", "port '" + p + "' is not an integer in [1, 65535]");
        l["port"] = std::stoul(p);
    }
    if (!rw.live_bind.empty()) l["bind"] = rw.live_bind;
    if (rw.live_decimation > 0) l["decimation"] = rw.live_decimation;
    // Default: every data topic a member of the run writes, and the viewer channels when the run writes their inputs
    // (Truth and the three estimates); `viewer` in --live-topics adds them to the listed topics.
    auto [names, viewer] = split_viewer(rw.live_topics);
    if (rw.live_topics.empty()) {
        std::set<std::string> written;
        for (const auto& c : rc.build(reg))
            for (const auto* o : c->outputs()) written.insert(o->topic());
        for (const auto& t : framework::known_topics())
            if (written.count(t)) names.push_back(t);
        const auto& inputs = io::viewer::viewer_input_topics();
        viewer = std::all_of(inputs.begin(), inputs.end(), [&](const std::string& t) { return written.count(t) > 0; });
        if (names.empty()) fail("--live", "no member of the run writes a data topic (give --live-topics)");
        spdlog::info("--live: member '{}' streams {}{}", kLiveName, join(names), viewer ? " and the viewer channels" : "");
    }
    if (!names.empty()) l["topics"] = sequence(resolve_topics(names, "--live-topics", true));
    else l["topics"] = YAML::Node(YAML::NodeType::Sequence);  // the viewer channels only
    l["viewer"] = viewer;
    comps[kLiveName] = l;
}

}  // namespace

RunConfig apply_run_rewrites(const RunConfig& rc, const RunRewrites& rw, const framework::ComponentRegistry& reg) {
    if (rw.replay_dir.empty() && !rw.replay_topics.empty()) fail("--topics", "needs --replay RUN_DIR");
    YAML::Node root = YAML::Load(rc.to_yaml());
    if (!rw.record.empty()) add_recorder(root["components"], rw.record);
    if (!rw.replay_dir.empty()) add_replay(root, rc, rw, reg);
    add_live(root["components"], rc, rw, reg);
    YAML::Emitter em;
    em.SetDoublePrecision(17);
    em << root;
    return RunConfig::parse(std::string(em.c_str()) + "\n", rc.origin);
}

}  // namespace gdnav::launch
