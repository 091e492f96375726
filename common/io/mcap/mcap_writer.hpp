#pragma once
// A small MCAP writer (https://mcap.dev/spec): one indexed, chunked file.
//
//   <magic><Header><Schema..><Channel..><Metadata..>[<Chunk><MessageIndex..>]..<Attachment..><DataEnd>
//   <summary: Schema.. Channel.. Statistics ChunkIndex.. AttachmentIndex.. MetadataIndex..>
//   <SummaryOffset per group><Footer><magic>
//
// Schemas, channels, metadata and attachments are written to the data section when added (outside chunks).
// Messages are gathered into a chunk; when its records reach `chunk_bytes` the chunk is compressed (zstd, or stored
// when `compression` is empty), written with its Message Index records and flushed to disk, so a file cut anywhere
// (a killed run) keeps every earlier chunk readable by a linear scan. close() writes the last chunk, Data End (with
// the data-section CRC-32) and the summary with its offsets and CRC.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "io/mcap/mcap_format.hpp"

namespace gdnav::io::mcap {

struct WriterOptions {
    std::string profile;             // Header.profile ("" = none of the well-known profiles)
    std::string library;             // Header.library (writer name and version)
    std::string compression{"zstd"};  // "zstd" or "" (uncompressed chunks)
    int zstd_level{-1};  // gdnav's samples are noisy doubles: higher levels barely shrink them and are much slower
                         // (docs/viewing.md, "Size and cost")
    std::size_t chunk_bytes{1u << 20};  // uncompressed records per chunk before it is written
};

class Writer {
public:
    Writer(const std::filesystem::path& file, WriterOptions options);
    ~Writer();  // closes the file if close() was not called (a complete file)
    Writer(const Writer&) = delete;
    Writer& operator=(const Writer&) = delete;

    // Returns the schema id (1, 2, ...).
    std::uint16_t add_schema(const std::string& name, const std::string& encoding, const std::string& data);
    // Returns the channel id (0, 1, ...).
    std::uint16_t add_channel(std::uint16_t schema_id, const std::string& topic, const std::string& message_encoding,
                              const StringMap& metadata = {});
    void write_message(std::uint16_t channel_id, std::uint32_t sequence, std::uint64_t log_time,
                       std::uint64_t publish_time, const std::uint8_t* data, std::size_t size);
    void write_metadata(const std::string& name, const StringMap& metadata);
    void write_attachment(const std::string& name, const std::string& media_type, std::uint64_t log_time,
                          std::uint64_t create_time, const std::string& data);
    void close();

    [[nodiscard]] std::uint64_t bytes_written() const { return offset_; }
    [[nodiscard]] std::uint64_t message_count() const { return message_count_; }
    [[nodiscard]] const std::filesystem::path& path() const { return path_; }

private:
    struct ChunkIndexEntry {
        std::uint64_t start_time, end_time, offset, length;
        std::map<std::uint16_t, std::uint64_t> message_index_offsets;
        std::uint64_t message_index_length, compressed_size, uncompressed_size;
    };
    struct AttachmentIndexEntry {
        std::uint64_t offset, length, log_time, create_time, data_size;
        std::string name, media_type;
    };
    struct MetadataIndexEntry {
        std::uint64_t offset, length;
        std::string name;
    };
    void emit(const std::vector<std::uint8_t>& bytes, bool data_section);
    void flush_chunk();
    // The summary section's records (close()).
    void write_statistics(std::vector<std::uint8_t>& s) const;
    void write_chunk_indexes(std::vector<std::uint8_t>& s) const;
    void write_attachment_indexes(std::vector<std::uint8_t>& s) const;
    void write_metadata_indexes(std::vector<std::uint8_t>& s) const;

    std::filesystem::path path_;
    WriterOptions opt_;
    std::FILE* file_{nullptr};
    std::uint64_t offset_{0};
    std::uint32_t data_crc_{0};
    std::vector<std::uint8_t> schema_records_, channel_records_;  // copies for the summary
    std::uint16_t schemas_{0}, channels_{0};
    // the open chunk
    std::vector<std::uint8_t> chunk_;
    std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunk_index_;  // channel -> (time, offset)
    std::uint64_t chunk_start_{0}, chunk_end_{0};
    // statistics and indexes
    std::uint64_t message_count_{0}, start_time_{0}, end_time_{0};
    std::map<std::uint16_t, std::uint64_t> channel_counts_;
    std::vector<ChunkIndexEntry> chunks_;
    std::vector<AttachmentIndexEntry> attachments_;
    std::vector<MetadataIndexEntry> metadata_;
    std::vector<std::uint8_t> scratch_;
};

}  // namespace gdnav::io::mcap
