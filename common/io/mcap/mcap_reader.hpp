#pragma once
// A small MCAP reader (https://mcap.dev/spec) for the files mcap_writer.hpp writes and any other well-formed MCAP
// with uncompressed or zstd chunks (lz4 chunks are reported as unsupported).
//
// read() scans the file from the start (the data section: schemas, channels, messages in and out of chunks,
// metadata, attachments), checks every chunk's CRC before handing its messages on, then reads the summary and
// footer and checks the data-section and summary CRCs and the statistics. A file that ends early or is damaged
// (a run killed mid-write) is not an exception: everything before the first bad record is returned, `complete` is
// false and `problem` says where and what ("truncated at byte N: ..."). Only an unreadable file or one that is
// not an MCAP at all (magic, header) throws std::runtime_error.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "io/mcap/mcap_format.hpp"

namespace gdnav::io::mcap {

struct Schema {
    std::uint16_t id{0};
    std::string name, encoding, data;
};

struct Channel {
    std::uint16_t id{0}, schema_id{0};
    std::string topic, message_encoding;
    StringMap metadata;
};

struct MessageView {
    const Channel* channel{nullptr};  // its channel (read before it)
    const Schema* schema{nullptr};    // the channel's schema (nullptr: schema id 0 or not in the file)
    std::uint16_t channel_id{0};
    std::uint32_t sequence{0};
    std::uint64_t log_time{0}, publish_time{0};
    const std::uint8_t* data{nullptr};  // valid during the callback only
    std::size_t size{0};
};

struct Metadata {
    std::string name;
    StringMap entries;
};

struct Attachment {
    std::string name, media_type;
    std::uint64_t log_time{0}, create_time{0};
    std::string data;
};

struct Statistics {
    std::uint64_t message_count{0};
    std::uint16_t schema_count{0};
    std::uint32_t channel_count{0}, attachment_count{0}, metadata_count{0}, chunk_count{0};
    std::uint64_t message_start_time{0}, message_end_time{0};
    std::map<std::uint16_t, std::uint64_t> channel_message_counts;
};

struct ChunkIndex {
    std::uint64_t message_start_time{0}, message_end_time{0}, chunk_start_offset{0}, chunk_length{0};
    std::map<std::uint16_t, std::uint64_t> message_index_offsets;
    std::uint64_t message_index_length{0};
    std::string compression;
    std::uint64_t compressed_size{0}, uncompressed_size{0};
};

struct ReadResult {
    std::string profile, library;
    std::map<std::uint16_t, Schema> schemas;
    std::map<std::uint16_t, Channel> channels;
    std::vector<Metadata> metadata;
    std::vector<Attachment> attachments;
    std::uint64_t messages{0};  // handed to the callback
    std::uint64_t chunks{0};    // read from the data section
    std::optional<Statistics> statistics;  // from the summary
    std::vector<ChunkIndex> chunk_indexes;  // from the summary
    bool complete{false};       // data end, summary, footer and closing magic read; CRCs and statistics agree
    std::string problem;        // why not complete (empty when complete)
    std::uint64_t readable_bytes{0};  // the data section is readable up to this offset
};

ReadResult read(const std::filesystem::path& file, const std::function<void(const MessageView&)>& on_message);

// Only the footer and the summary section (what an indexed reader starts with): profile and library stay empty,
// no messages are read; schemas, channels, statistics and chunk indexes come from the summary. `complete` is false
// (with `problem`) when the file has no valid footer, closing magic or summary, e.g. a recording cut short.
ReadResult read_summary(const std::filesystem::path& file);

}  // namespace gdnav::io::mcap
