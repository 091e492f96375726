#include "io/recording/record_file.hpp"

#include <yaml-cpp/yaml.h>

#include <spdlog/spdlog.h>

#include <cmath>
#include <cstring>
#include <set>
#include <stdexcept>

#include "io/mcap/mcap_reader.hpp"
#include "framework/topic_types.hpp"
#include "io/viewer/viewer_channels.hpp"

namespace gdnav::io::recording {

namespace fs = std::filesystem;

namespace {
struct SampleDeleter {
    const msg::MessageOps* ops;
    void operator()(void* p) const { ops->destroy(p); }
};
}  // namespace

std::uint64_t fnv1a(std::uint64_t h, const std::uint8_t* p, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
        h ^= p[i];
        h *= 0x100000001b3ULL;
    }
    return h;
}

std::uint64_t digest_sample(std::uint64_t h, std::uint64_t step, const std::uint8_t* cdr, std::uint32_t n) {
    std::uint8_t head[12];
    for (int i = 0; i < 8; ++i) head[i] = static_cast<std::uint8_t>(step >> (8 * i));
    for (int i = 0; i < 4; ++i) head[8 + i] = static_cast<std::uint8_t>(n >> (8 * i));
    return fnv1a(fnv1a(h, head, sizeof(head)), cdr, n);
}

std::string digest_hex(std::uint64_t digest) {
    char hex[20];
    std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(digest));
    return hex;
}

fs::path recording_file(const fs::path& dir) { return dir / kRecordingFile; }

std::uint64_t step_ns(double dt_s) { return static_cast<std::uint64_t>(std::llround(dt_s * 1e9)); }

std::string resolve_topic(const std::string& name) {
    if (framework::find_topic(name)) return name;
    const std::string full = "gdnav/" + name;
    if (name.find('/') == std::string::npos && framework::find_topic(full)) return full;
    return {};
}

std::string known_topics_list() {
    std::string known;
    for (const auto& k : framework::known_topics()) known += (known.empty() ? "" : ", ") + k;
    return known;
}

// ------------------------------------------------------------------------------------------------ reading
namespace {

// A viewer channel (common/io/viewer) that gdnav wrote: derived data, skipped by gdnav's reader.
bool is_derived(const mcap::Channel& c, const mcap::Schema* schema) {
    return schema && viewer::is_viewer_channel(c.topic, schema->name, schema->encoding, c.message_encoding);
}

// Checks a channel against gdnav's topics; the error names the channel.
void check_channel(const fs::path& file, const mcap::Channel& c, const mcap::Schema* schema) {
    const std::string where = file.string() + ": channel '" + c.topic + "' (id " + std::to_string(c.id) + ")";
    const msg::MessageOps* ops = framework::find_topic(c.topic);
    if (!ops)
        throw std::runtime_error(where + " is not a gdnav topic (not a gdnav recording? known topics: " +
                                 known_topics_list() + ")");
    if (c.message_encoding != kMessageEncoding)
        throw std::runtime_error(where + ": message encoding '" + c.message_encoding + "', gdnav records '" +
                                 kMessageEncoding + "'");
    if (!schema) throw std::runtime_error(where + ": no schema (id " + std::to_string(c.schema_id) + ")");
    if (schema->name != ops->type_name || schema->encoding != kSchemaEncoding)
        throw std::runtime_error(where + ": schema '" + schema->name + "' (" + schema->encoding + "), gdnav's is '" +
                                 ops->type_name + "' (" + kSchemaEncoding + ")");
}

}  // namespace

namespace {

// Collects the messages of the wanted topics while the file is read. Channels are validated at their first message
// (a channel record precedes its messages); the first problem is kept and thrown after the scan.
class MessageCollector {
public:
    MessageCollector(Recording& rec, const std::vector<std::string>& wanted)
        : rec_(rec), file_(rec.file.string()), want_(wanted.begin(), wanted.end()) {}

    void operator()(const mcap::MessageView& m) {
        if (!error_.empty()) return;
        auto it = tracks_.find(m.channel_id);
        if (it == tracks_.end()) {
            if (!open_track(m)) return;
            it = tracks_.find(m.channel_id);
        }
        Track& t = it->second;
        const std::uint64_t index = t.index++;
        if (t.record) keep(t, m, index);
    }

    [[nodiscard]] const std::string& error() const { return error_; }

private:
    struct Track {
        TopicRecord* record{nullptr};  // nullptr: a channel not asked for
        std::unique_ptr<SampleDecoder> decoder;
        std::unique_ptr<void, SampleDeleter> sample{nullptr, SampleDeleter{nullptr}};
        std::uint64_t index{0};
    };

    // The first message of a channel: checks the channel; a derived or unwanted channel gets an empty track.
    bool open_track(const mcap::MessageView& m) {
        Track t;
        const mcap::Channel& c = *m.channel;
        if (is_derived(c, m.schema)) {  // skipped: nothing to check or keep
            tracks_.emplace(m.channel_id, std::move(t));
            return false;
        }
        try {
            check_channel(rec_.file, c, m.schema);
        } catch (const std::runtime_error& e) {
            error_ = e.what();
            return false;
        }
        if (want_.empty() || want_.count(c.topic)) {
            TopicRecord& tr = rec_.topics[c.topic];
            tr.topic = c.topic;
            tr.file = rec_.file;
            tr.ops = framework::find_topic(c.topic);
            t.record = &tr;
            t.decoder = std::make_unique<SampleDecoder>(*tr.ops);
            t.sample = std::unique_ptr<void, SampleDeleter>(tr.ops->create(), SampleDeleter{tr.ops});
        }
        tracks_.emplace(m.channel_id, std::move(t));
        return true;
    }

    void keep(Track& t, const mcap::MessageView& m, std::uint64_t index) {
        TopicRecord& tr = *t.record;
        // The step: the message's sequence, i.e. the step the recorder recorded it at (runs have at most 10^8
        // steps, RunConfig). Not the sample's own stamp: a delayed sample (fault `delay`) carries its older stamp.
        const std::uint64_t step = m.sequence;
        auto fail = [&](const std::string& what) {
            error_ = file_ + ": " + tr.topic + ": message " + std::to_string(index) + " (step " +
                     std::to_string(step) + "): " + what;
        };
        if (m.size == 0 || m.size > (1u << 20)) return fail("implausible sample size " + std::to_string(m.size) + " bytes");
        const auto n = static_cast<std::uint32_t>(m.size);
        if (!t.decoder->decode(m.data, n, t.sample.get()))
            return fail("the payload is not a " + std::string(tr.ops->type_name) + " sample");
        if (!tr.entries.empty() && step <= tr.entries.back().step)
            return fail("after step " + std::to_string(tr.entries.back().step) + " (steps must increase)");
        tr.entries.push_back({step, tr.bytes.size(), n});
        tr.bytes.insert(tr.bytes.end(), m.data, m.data + n);
        tr.digest = digest_sample(tr.digest, step, m.data, n);
    }

    Recording& rec_;
    std::string file_;
    std::set<std::string> want_;
    std::map<std::uint16_t, Track> tracks_;
    std::string error_;
};

// Channels without messages are checked too (a foreign channel is refused even when empty).
void check_all_channels(Recording& rec, const mcap::ReadResult& r) {
    for (const auto& [id, c] : r.channels) {
        const auto s = r.schemas.find(c.schema_id);
        const mcap::Schema* schema = s == r.schemas.end() ? nullptr : &s->second;
        if (is_derived(c, schema)) {
            rec.derived_channels.push_back(c.topic);
            continue;
        }
        check_channel(rec.file, c, schema);
        rec.channels.push_back(c.topic);
    }
}

// A wanted topic with a channel but no message gets an empty record; one without a channel is an error.
void add_empty_wanted(Recording& rec, const std::vector<std::string>& wanted) {
    for (const auto& topic : wanted) {
        if (rec.topics.count(topic)) continue;
        bool has_channel = false;
        for (const auto& c : rec.channels) has_channel = has_channel || c == topic;
        if (!has_channel) {
            std::string there;
            for (const auto& c : rec.channels) there += (there.empty() ? "" : ", ") + c;
            throw std::runtime_error(rec.file.string() + ": no channel " + topic + " (no record of " + topic +
                                     "; recorded: " + (there.empty() ? "nothing" : there) + ")");
        }
        TopicRecord& tr = rec.topics[topic];
        tr.topic = topic;
        tr.file = rec.file;
        tr.ops = framework::find_topic(topic);
    }
}

void warn_incomplete(const Recording& rec, const mcap::ReadResult& r) {
    std::string got;
    for (const auto& [topic, tr] : rec.topics)
        got += (got.empty() ? "" : ", ") + topic + " " + std::to_string(tr.entries.size()) +
               (tr.entries.empty() ? "" : " (steps " + std::to_string(tr.entries.front().step) + ".." +
                                              std::to_string(tr.entries.back().step) + ")");
    spdlog::warn("{}: incomplete MCAP file (recording cut short?) — {}; read the {} messages before it: {}",
                 rec.file.string(), r.problem, r.messages, got.empty() ? "none" : got);
}

}  // namespace

Recording read_recording(const fs::path& dir, const std::vector<std::string>& wanted) {
    Recording rec;
    rec.file = recording_file(dir);
    std::error_code ec;
    if (!fs::is_regular_file(rec.file, ec))
        throw std::runtime_error(rec.file.string() + ": missing (no recording in " + dir.string() + ")");
    MessageCollector collect(rec, wanted);
    const mcap::ReadResult r = mcap::read(rec.file, [&](const mcap::MessageView& m) { collect(m); });
    if (!collect.error().empty()) throw std::runtime_error(collect.error());
    check_all_channels(rec, r);
    add_empty_wanted(rec, wanted);
    for (const auto& m : r.metadata)
        if (m.name == kRunMetadataName) rec.run_metadata = m.entries;
    for (const auto& a : r.attachments)
        if (a.name == kRunYamlAttachment) rec.run_yaml = a.data;
    rec.complete = r.complete;
    rec.problem = r.problem;
    if (!r.complete) warn_incomplete(rec, r);
    return rec;
}

std::vector<std::string> recorded_topics(const fs::path& dir) {
    const fs::path file = recording_file(dir);
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) throw std::runtime_error(file.string() + ": missing (no recording in " + dir.string() + ")");
    mcap::ReadResult r = mcap::read_summary(file);
    if (!r.complete) r = mcap::read(file, [](const mcap::MessageView&) {});
    std::vector<std::string> v;
    for (const auto& [id, c] : r.channels) {
        const auto s = r.schemas.find(c.schema_id);
        const mcap::Schema* schema = s == r.schemas.end() ? nullptr : &s->second;
        if (is_derived(c, schema)) continue;
        check_channel(file, c, schema);
        v.push_back(c.topic);
    }
    return v;
}

TopicRecord read_topic_record(const fs::path& dir, const std::string& topic) {
    if (!framework::find_topic(topic))
        throw std::runtime_error("unknown topic '" + topic + "' (known: " + known_topics_list() + ")");
    Recording rec = read_recording(dir, {topic});
    return std::move(rec.topics.at(topic));
}

DigestFile read_digest_file(const fs::path& dir) {
    DigestFile d;
    const fs::path f = dir / "digest.yaml";
    std::error_code ec;
    if (!fs::exists(f, ec)) return d;
    d.present = true;
    try {
        const YAML::Node n = YAML::LoadFile(f.string());
        d.complete = n["complete"] && n["complete"].as<bool>();
        if (n["topics"])
            for (const auto& kv : n["topics"]) d.digests[kv.first.as<std::string>()] = kv.second["digest"].as<std::string>();
    } catch (const YAML::Exception& e) {
        throw std::runtime_error(f.string() + ": malformed (" + e.what() + ")");
    }
    return d;
}

}  // namespace gdnav::io::recording
