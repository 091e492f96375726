#pragma once
// The runtime recorder's recording, written by the recorder (and `gdnav import-log`) and read back by the replay
// component and `gdnav export-log`:
//   <dir>/run.mcap     one indexed, zstd-chunked MCAP file (common/io/mcap, https://mcap.dev/spec; docs/viewing.md):
//                      a channel per recorded topic (topic = the gdnav topic name, message encoding `cdr`, schema
//                      encoding `omgidl`, schema name = the fully-qualified IDL type, schema data = the IDL text);
//                      one message per recorded step: sequence = step k (mod 2^32; the sample's stamp carries
//                      the full step), log time = publish time = k * dt_ns
//                      (dt_ns = round(dt_s * 1e9)) nanoseconds after step 0, i.e. the epoch is the run's t0_s;
//                      data = the sample's CDR encoding with its 4-byte encapsulation header (padding zeroed).
//                      Metadata "gdnav.run" (run_metadata.hpp) and the run's configuration as attachment run.yaml.
//   <dir>/digest.yaml  complete: true|false, topics: {TOPIC: {samples, last_step, digest: FNV-1a 64 hex}} — the
//                      digest runs over (u64 step, u32 size, CDR bytes) of every sample, so two runs are
//                      bit-identical iff their digests are equal, whatever the container.
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "io/mcap/mcap_format.hpp"
#include "msgs/message_ops.hpp"

namespace gdnav::io::recording {

inline constexpr const char* kRecordingFile = "run.mcap";
inline constexpr const char* kMessageEncoding = mcap::kCdr;
inline constexpr const char* kSchemaEncoding = mcap::kOmgIdl;
inline constexpr const char* kProfile = "x-gdnav";
inline constexpr const char* kRunMetadataName = "gdnav.run";
inline constexpr const char* kEndMetadataName = "gdnav.end";
inline constexpr const char* kRunYamlAttachment = "run.yaml";

inline constexpr std::uint64_t kFnvBasis = 0xcbf29ce484222325ULL;
std::uint64_t fnv1a(std::uint64_t h, const std::uint8_t* p, std::size_t n);
// Continues a topic digest with the record of one sample: u64 step LE, u32 size LE, then the CDR bytes.
std::uint64_t digest_sample(std::uint64_t h, std::uint64_t step, const std::uint8_t* cdr, std::uint32_t n);
std::string digest_hex(std::uint64_t digest);

// <dir>/run.mcap
std::filesystem::path recording_file(const std::filesystem::path& dir);
// Nanoseconds per step in the recording's log times (round(dt_s * 1e9)).
std::uint64_t step_ns(double dt_s);
// A data topic by its full ("gdnav/ImuSample") or short ("ImuSample") name -> full name; empty when unknown.
std::string resolve_topic(const std::string& name);
// The known data topics, comma separated (for error messages).
std::string known_topics_list();

// Decodes CDR payloads of one topic's type (the type's message operations: msg::MessageOps::deserialize).
class SampleDecoder {
public:
    explicit SampleDecoder(const msg::MessageOps& ops) : ops_(&ops) {}
    // Deserialises n bytes into `sample` (an object of the topic's type); false when the bytes are not a sample.
    bool decode(const std::uint8_t* bytes, std::uint32_t n, void* sample) { return ops_->deserialize(bytes, n, sample); }

private:
    const msg::MessageOps* ops_;
};

struct RecordEntry {
    std::uint64_t step;
    std::size_t offset;  // of the payload in TopicRecord::bytes
    std::uint32_t size;
};

// One topic's messages, read from the recording and checked.
struct TopicRecord {
    std::string topic;
    std::filesystem::path file;        // the MCAP file
    const msg::MessageOps* ops{nullptr};
    std::vector<std::uint8_t> bytes;   // the CDR payloads, one after the other
    std::vector<RecordEntry> entries;  // strictly increasing steps
    std::uint64_t digest{kFnvBasis};   // as digest.yaml
};

// A recording read back.
struct Recording {
    std::filesystem::path file;
    std::map<std::string, TopicRecord> topics;  // the topics asked for
    std::vector<std::string> channels;          // every gdnav topic channel's topic, in channel order
    std::vector<std::string> derived_channels;  // the viewer channels (common/io/viewer): skipped, not decoded
    std::map<std::string, std::string> run_metadata;  // the "gdnav.run" metadata record
    std::string run_yaml;                       // the run.yaml attachment ("" when absent)
    bool complete{false};  // the MCAP file is whole (summary, footer, CRCs); false for a run killed mid-write
    std::string problem;   // why not complete, with the byte offset of the cut
};

// Reads <dir>/run.mcap: every channel must be a known gdnav topic in CDR with its omgidl schema, or one of gdnav's
// viewer channels (common/io/viewer/viewer_channels.hpp; listed in derived_channels, messages skipped) (anything else —
// an MCAP written by another tool — throws std::runtime_error "FILE: channel 'TOPIC' (id N): ..."); each topic of
// `topics` (full names; empty: every channel) must have a channel; its messages are checked: every payload decodes
// as the topic's type and the messages' sequences (the recorded steps; a delayed sample keeps its older stamp) strictly
// increase.
// A file cut short (run killed) is not an error: the messages of its complete chunks are returned, `complete` is
// false, `problem` says where it ends, and a warning is logged. Throws std::runtime_error "FILE: ..." on the first
// problem otherwise.
Recording read_recording(const std::filesystem::path& dir, const std::vector<std::string>& topics = {});

// The topics of the recording's channels (viewer channels left out), from its summary (quick), or from a scan when it
// has none (cut short).
// Throws as read_recording() on a channel that is not a gdnav topic.
std::vector<std::string> recorded_topics(const std::filesystem::path& dir);

// One topic (read_recording(dir, {topic}).topics[topic]).
TopicRecord read_topic_record(const std::filesystem::path& dir, const std::string& topic);

// What digest.yaml says (present = the file exists).
struct DigestFile {
    bool present{false};
    bool complete{false};
    std::map<std::string, std::string> digests;  // topic -> hex
};
// Throws std::runtime_error when digest.yaml exists but is malformed.
DigestFile read_digest_file(const std::filesystem::path& dir);

}  // namespace gdnav::io::recording
