#include "io/mcap/mcap_writer.hpp"

#include <zstd.h>

#include <algorithm>
#include <cerrno>
#include <stdexcept>
#include <tuple>

#include "files/write_error.hpp"
#include "io/mcap/crc32.hpp"

namespace gdnav::io::mcap {

Writer::Writer(const std::filesystem::path& file, WriterOptions options) : path_(file), opt_(std::move(options)) {
    if (opt_.compression != "zstd" && !opt_.compression.empty())
        throw std::invalid_argument("mcap: compression '" + opt_.compression + "' (supported: zstd, none)");
    file_ = std::fopen(path_.c_str(), "wb");
    if (!file_) files::throw_write_error(path_, errno);
    std::vector<std::uint8_t> b(kMagic, kMagic + 8);
    ByteWriter w(b);
    const std::size_t at = w.begin_record(Op::Header);
    w.fields(opt_.profile, opt_.library);
    w.end_record(at);
    emit(b, true);
}

Writer::~Writer() {
    try {
        close();
    } catch (const std::exception&) {
        // a destructor cannot report; close() explicitly to see write errors
    }
}

void Writer::emit(const std::vector<std::uint8_t>& bytes, bool data_section) {
    if (!file_) throw std::logic_error("mcap: " + path_.string() + " is closed");
    if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) files::throw_write_error(path_, errno);
    if (data_section) data_crc_ = crc32_update(data_crc_, bytes.data(), bytes.size());
    offset_ += bytes.size();
}

std::uint16_t Writer::add_schema(const std::string& name, const std::string& encoding, const std::string& data) {
    const auto id = static_cast<std::uint16_t>(++schemas_);
    scratch_.clear();
    ByteWriter w(scratch_);
    const std::size_t at = w.begin_record(Op::Schema);
    w.fields(id, name, encoding, data);
    w.end_record(at);
    emit(scratch_, true);
    schema_records_.insert(schema_records_.end(), scratch_.begin(), scratch_.end());
    return id;
}

std::uint16_t Writer::add_channel(std::uint16_t schema_id, const std::string& topic,
                                  const std::string& message_encoding, const StringMap& metadata) {
    const std::uint16_t id = channels_++;
    scratch_.clear();
    ByteWriter w(scratch_);
    const std::size_t at = w.begin_record(Op::Channel);
    w.fields(id, schema_id, topic, message_encoding, metadata);
    w.end_record(at);
    emit(scratch_, true);
    channel_records_.insert(channel_records_.end(), scratch_.begin(), scratch_.end());
    channel_counts_[id] = 0;
    return id;
}

void Writer::write_message(std::uint16_t channel_id, std::uint32_t sequence, std::uint64_t log_time,
                           std::uint64_t publish_time, const std::uint8_t* data, std::size_t size) {
    if (channel_id >= channels_) throw std::logic_error("mcap: message on unknown channel " + std::to_string(channel_id));
    if (chunk_.empty()) chunk_start_ = chunk_end_ = log_time;
    chunk_start_ = std::min(chunk_start_, log_time);
    chunk_end_ = std::max(chunk_end_, log_time);
    chunk_index_[channel_id].emplace_back(log_time, chunk_.size());
    ByteWriter w(chunk_);
    const std::size_t at = w.begin_record(Op::Message);
    w.fields(channel_id, sequence, log_time, publish_time);
    w.bytes(data, size);
    w.end_record(at);
    if (message_count_ == 0) start_time_ = end_time_ = log_time;
    start_time_ = std::min(start_time_, log_time);
    end_time_ = std::max(end_time_, log_time);
    ++message_count_;
    ++channel_counts_[channel_id];
    if (chunk_.size() >= opt_.chunk_bytes) flush_chunk();
}

void Writer::flush_chunk() {
    if (chunk_.empty()) return;
    std::vector<std::uint8_t> compressed;
    const std::vector<std::uint8_t>* records = &chunk_;
    if (opt_.compression == "zstd") {
        compressed.resize(ZSTD_compressBound(chunk_.size()));
        const std::size_t n = ZSTD_compress(compressed.data(), compressed.size(), chunk_.data(), chunk_.size(),
                                            opt_.zstd_level);
        if (ZSTD_isError(n)) throw std::runtime_error(std::string("mcap: zstd: ") + ZSTD_getErrorName(n));
        compressed.resize(n);
        records = &compressed;
    }
    ChunkIndexEntry ci{};
    ci.start_time = chunk_start_;
    ci.end_time = chunk_end_;
    ci.offset = offset_;
    ci.compressed_size = records->size();
    ci.uncompressed_size = chunk_.size();
    scratch_.clear();
    ByteWriter w(scratch_);
    const std::size_t at = w.begin_record(Op::Chunk);
    w.u64(chunk_start_);
    w.u64(chunk_end_);
    w.u64(chunk_.size());
    w.u32(crc32_update(0, chunk_.data(), chunk_.size()));
    w.str(opt_.compression);
    w.u64(records->size());
    w.bytes(records->data(), records->size());
    w.end_record(at);
    ci.length = scratch_.size();
    // Message Index records, one per channel in the chunk, right after it.
    std::uint64_t at_file = offset_ + scratch_.size();
    const std::size_t index_begin = scratch_.size();
    for (const auto& [channel, entries] : chunk_index_) {
        ci.message_index_offsets[channel] = at_file + (scratch_.size() - index_begin);
        const std::size_t rec = w.begin_record(Op::MessageIndex);
        w.u16(channel);
        w.u32(static_cast<std::uint32_t>(entries.size() * 16));
        for (const auto& [t, off] : entries) {
            w.u64(t);
            w.u64(off);
        }
        w.end_record(rec);
    }
    ci.message_index_length = scratch_.size() - index_begin;
    emit(scratch_, true);
    if (std::fflush(file_) != 0) files::throw_write_error(path_, errno);
    chunks_.push_back(std::move(ci));
    chunk_.clear();
    chunk_index_.clear();
}

void Writer::write_metadata(const std::string& name, const StringMap& metadata) {
    scratch_.clear();
    ByteWriter w(scratch_);
    const std::size_t at = w.begin_record(Op::Metadata);
    w.fields(name, metadata);
    w.end_record(at);
    metadata_.push_back({offset_, scratch_.size(), name});
    emit(scratch_, true);
}

void Writer::write_attachment(const std::string& name, const std::string& media_type, std::uint64_t log_time,
                              std::uint64_t create_time, const std::string& data) {
    scratch_.clear();
    ByteWriter w(scratch_);
    const std::size_t at = w.begin_record(Op::Attachment);
    w.fields(log_time, create_time, name, media_type, data.size());
    w.bytes(reinterpret_cast<const std::uint8_t*>(data.data()), data.size());
    // CRC-32 of the preceding fields of the record's content
    w.u32(crc32_update(0, scratch_.data() + kRecordPrefix, scratch_.size() - kRecordPrefix));
    w.end_record(at);
    attachments_.push_back({offset_, scratch_.size(), log_time, create_time, data.size(), name, media_type});
    emit(scratch_, true);
}

void Writer::write_statistics(std::vector<std::uint8_t>& s) const {
    ByteWriter w(s);
    const std::size_t at = w.begin_record(Op::Statistics);
    w.fields(message_count_, schemas_, std::uint32_t{channels_}, static_cast<std::uint32_t>(attachments_.size()),
             static_cast<std::uint32_t>(metadata_.size()), static_cast<std::uint32_t>(chunks_.size()), start_time_,
             end_time_);
    w.channel_map(channel_counts_);
    w.end_record(at);
}

void Writer::write_chunk_indexes(std::vector<std::uint8_t>& s) const {
    ByteWriter w(s);
    for (const auto& c : chunks_) {
        const std::size_t at = w.begin_record(Op::ChunkIndex);
        w.fields(c.start_time, c.end_time, c.offset, c.length);
        w.channel_map(c.message_index_offsets);
        w.fields(c.message_index_length, opt_.compression, c.compressed_size, c.uncompressed_size);
        w.end_record(at);
    }
}

void Writer::write_attachment_indexes(std::vector<std::uint8_t>& s) const {
    ByteWriter w(s);
    for (const auto& a : attachments_) {
        const std::size_t at = w.begin_record(Op::AttachmentIndex);
        w.fields(a.offset, a.length, a.log_time, a.create_time, a.data_size, a.name, a.media_type);
        w.end_record(at);
    }
}

void Writer::write_metadata_indexes(std::vector<std::uint8_t>& s) const {
    ByteWriter w(s);
    for (const auto& m : metadata_) {
        const std::size_t at = w.begin_record(Op::MetadataIndex);
        w.fields(m.offset, m.length, m.name);
        w.end_record(at);
    }
}

void Writer::close() {
    if (!file_) return;
    flush_chunk();
    {
        std::vector<std::uint8_t> b;
        ByteWriter w(b);
        const std::size_t at = w.begin_record(Op::DataEnd);
        w.u32(data_crc_);
        w.end_record(at);
        emit(b, false);
    }
    // Summary section, grouped by opcode; `groups` remembers each group's span for the Summary Offset records.
    const std::uint64_t summary_start = offset_;
    std::vector<std::uint8_t> s;
    ByteWriter w(s);
    std::vector<std::tuple<Op, std::uint64_t, std::uint64_t>> groups;
    auto group = [&](Op op, auto&& body) {
        const std::size_t begin = s.size();
        body();
        if (s.size() > begin) groups.emplace_back(op, summary_start + begin, s.size() - begin);
    };
    group(Op::Schema, [&] { w.bytes(schema_records_.data(), schema_records_.size()); });
    group(Op::Channel, [&] { w.bytes(channel_records_.data(), channel_records_.size()); });
    group(Op::Statistics, [&] { write_statistics(s); });
    group(Op::ChunkIndex, [&] { write_chunk_indexes(s); });
    group(Op::AttachmentIndex, [&] { write_attachment_indexes(s); });
    group(Op::MetadataIndex, [&] { write_metadata_indexes(s); });
    const std::uint64_t summary_offset_start = summary_start + s.size();
    for (const auto& [op, start, length] : groups) {
        const std::size_t at = w.begin_record(Op::SummaryOffset);
        w.u8(static_cast<std::uint8_t>(op));
        w.u64(start);
        w.u64(length);
        w.end_record(at);
    }
    // Footer: the summary CRC covers the summary, the offsets and the footer up to (not including) the CRC field.
    w.u8(static_cast<std::uint8_t>(Op::Footer));
    w.u64(kFooterContent);  // written out now: the CRC covers it
    w.u64(summary_start);
    w.u64(summary_offset_start);
    w.u32(crc32_update(0, s.data(), s.size()));
    w.bytes(kMagic, 8);
    emit(s, false);
    std::FILE* f = file_;
    file_ = nullptr;
    if (std::fclose(f) != 0) files::throw_write_error(path_, errno);
}

}  // namespace gdnav::io::mcap
