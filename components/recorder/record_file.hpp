#pragma once
// The runtime recorder's file format (components/recorder/recorder.hpp), written by the recorder and read back:
//   <dir>/<topic>.cdr  one record per recorded step: u64 step (little endian), u32 n, n bytes of the sample's CDR
//                      encoding (padding zeroed); '/' in the topic name becomes "__" (gdnav__ImuSample.cdr)
//   <dir>/digest.yaml  complete: true|false, topics: {TOPIC: {samples, last_step, digest: FNV-1a 64 hex}}
// Used by the recorder (writes), the replay component (reads), `gdnav export-log` (reads) and `gdnav import-log`
// (writes).
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <fastdds/dds/topic/TopicDataType.hpp>

#include "runtime/message_traits.hpp"

namespace gdnav::recorder {

inline constexpr std::uint64_t kFnvBasis = 0xcbf29ce484222325ULL;
std::uint64_t fnv1a(std::uint64_t h, const std::uint8_t* p, std::size_t n);
std::string digest_hex(std::uint64_t digest);

// "<topic with '/' -> '__'>.cdr", as the recorder names its files.
std::string record_file_name(const std::string& topic);
// A data topic by its full ("gdnav/ImuSample") or short ("ImuSample") name -> full name; empty when unknown.
std::string resolve_topic(const std::string& name);
// The known data topics, comma separated (for error messages).
std::string known_topics_list();

// Decodes CDR payloads of one topic's type (reuses one type support and one payload buffer).
class SampleDecoder {
public:
    explicit SampleDecoder(const runtime::MessageOps& ops);
    ~SampleDecoder();
    SampleDecoder(const SampleDecoder&) = delete;
    SampleDecoder& operator=(const SampleDecoder&) = delete;
    // Deserialises n bytes into `sample` (an object of the topic's type); false when the bytes are not a sample.
    bool decode(const std::uint8_t* bytes, std::uint32_t n, void* sample);

private:
    std::unique_ptr<eprosima::fastdds::dds::TopicDataType> type_;
    eprosima::fastrtps::rtps::SerializedPayload_t payload_;
};

struct RecordEntry {
    std::uint64_t step;
    std::size_t offset;  // of the payload in TopicRecord::bytes
    std::uint32_t size;
};

// One topic's record file, read fully into memory and checked.
struct TopicRecord {
    std::string topic;
    std::filesystem::path file;
    const runtime::MessageOps* ops{nullptr};
    std::vector<std::uint8_t> bytes;   // the whole file
    std::vector<RecordEntry> entries;  // strictly increasing steps
    std::uint64_t digest{kFnvBasis};   // FNV-1a 64 over all records (as digest.yaml)
};

// Reads <dir>/<record_file_name(topic)> and checks it: every record complete, steps strictly increasing, every
// payload a sample of the topic's type whose stamp carries the record's step. Throws std::runtime_error
// "FILE: record N (byte B): what" on the first problem (or "FILE: missing" / "cannot read").
TopicRecord read_topic_record(const std::filesystem::path& dir, const std::string& topic);

// What digest.yaml says (present = the file exists).
struct DigestFile {
    bool present{false};
    bool complete{false};
    std::map<std::string, std::string> digests;  // topic -> hex
};
// Throws std::runtime_error when digest.yaml exists but is malformed.
DigestFile read_digest_file(const std::filesystem::path& dir);

// Writes one topic's record file (truncates) and keeps its digest.
class RecordWriter {
public:
    RecordWriter(const std::filesystem::path& dir, const std::string& topic);
    // Serialises `sample` (an object of the topic's type) as the record of `step` (steps strictly increasing).
    void append(std::uint64_t step, const void* sample);
    void close();
    [[nodiscard]] const std::string& topic() const { return topic_; }
    [[nodiscard]] std::uint64_t samples() const { return samples_; }
    [[nodiscard]] std::uint64_t last_step() const { return last_step_; }
    [[nodiscard]] std::uint64_t digest() const { return digest_; }

private:
    std::string topic_;
    const runtime::MessageOps* ops_;
    std::filesystem::path path_;
    std::ofstream file_;
    std::vector<std::uint8_t> buffer_;
    std::uint64_t digest_{kFnvBasis};
    std::uint64_t samples_{0};
    std::uint64_t last_step_{0};
};

// digest.yaml for the given writers; `lost_at` adds lost_at_step to the topics whose producer died (recorder).
void write_digest_file(const std::filesystem::path& dir, const std::vector<const RecordWriter*>& writers,
                       bool complete, const std::map<std::string, std::uint64_t>& lost_at = {});

}  // namespace gdnav::recorder
