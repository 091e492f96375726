#include "io/mcap/mcap_reader.hpp"

#include <zstd.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "io/mcap/crc32.hpp"

namespace gdnav::io::mcap {

namespace {

// A record that cannot be used: where it starts and what is wrong.
struct Bad {
    std::uint64_t at;
    std::string what;
};

std::string op_name(std::uint8_t op) {
    static const char* const names[] = {"?",          "Header",        "Footer",          "Schema",
                                        "Channel",    "Message",       "Chunk",           "MessageIndex",
                                        "ChunkIndex", "Attachment",    "AttachmentIndex", "Statistics",
                                        "Metadata",   "MetadataIndex", "SummaryOffset",   "DataEnd"};
    if (op >= 1 && op <= 0x0F) return names[op];
    char buf[16];
    std::snprintf(buf, sizeof(buf), "op 0x%02x", op);
    return buf;
}

class Scanner {
public:
    Scanner(const std::vector<std::uint8_t>& file, ReadResult& r, const std::function<void(const MessageView&)>& cb)
        : f_(file), r_(r), cb_(cb) {}

    void run() {
        std::uint64_t pos = 8 + header();
        r_.readable_bytes = pos;
        // data section
        while (true) {
            const auto [op, content, n] = record_at(pos, "data section");
            ByteReader in(content, n);
            try {
                if (op == static_cast<std::uint8_t>(Op::DataEnd)) {
                    const std::uint32_t crc = in.u32();
                    const std::uint32_t actual = crc32_update(0, f_.data(), pos);
                    if (crc != 0 && crc != actual)
                        throw Bad{pos, "data section CRC-32 " + hex(actual) + " differs from Data End's " + hex(crc)};
                    pos += kRecordPrefix + n;
                    r_.readable_bytes = pos;
                    break;
                }
                data_record(op, in, pos);
            } catch (const std::out_of_range& e) {
                throw Bad{pos, op_name(op) + " record: " + e.what()};
            }
            pos += kRecordPrefix + n;
            r_.readable_bytes = pos;
        }
        summary(pos);
        r_.complete = true;
    }

    // The summary alone, from the footer at the end of the file.
    void run_summary() {
        if (f_.size() < 8 + kRecordPrefix + kFooterContent + 8 ||
            std::memcmp(f_.data() + f_.size() - 8, kMagic, 8) != 0)
            throw Bad{f_.size(), "no closing magic (file cut short?)"};
        const std::uint64_t footer_at = f_.size() - 8 - kRecordPrefix - kFooterContent;
        const auto [op, content, n] = record_at(footer_at, "footer");
        if (op != static_cast<std::uint8_t>(Op::Footer) || n != kFooterContent) throw Bad{footer_at, "no Footer record"};
        ByteReader in(content, n);
        const std::uint64_t start = in.u64();  // the rest is checked by footer()
        if (start == 0) throw Bad{footer_at, "the file has no summary section"};
        if (start >= footer_at) throw Bad{footer_at, "Footer.summary_start " + std::to_string(start) + " is past the footer"};
        for (std::uint64_t pos = start; pos < footer_at;) {
            const auto [rop, rc, rn] = record_at(pos, "summary");
            ByteReader rin(rc, rn);
            try {
                if (rop == static_cast<std::uint8_t>(Op::Schema)) schema(rin);
                if (rop == static_cast<std::uint8_t>(Op::Channel)) channel(rin);
                if (rop == static_cast<std::uint8_t>(Op::Statistics)) statistics(rin);
                if (rop == static_cast<std::uint8_t>(Op::ChunkIndex)) chunk_index(rin);
            } catch (const std::out_of_range& e) {
                throw Bad{pos, op_name(rop) + " record: " + e.what()};
            }
            pos += kRecordPrefix + rn;
        }
        footer(footer_at, start, false);
        r_.complete = true;
    }

private:
    static std::string hex(std::uint32_t v) {
        char buf[16];
        std::snprintf(buf, sizeof(buf), "0x%08x", v);
        return buf;
    }

    std::uint64_t header() {
        if (f_.size() < 8 || std::memcmp(f_.data(), kMagic, 8) != 0) throw std::runtime_error("not an MCAP file (magic)");
        if (f_.size() < 8 + kRecordPrefix || f_[8] != static_cast<std::uint8_t>(Op::Header))
            throw std::runtime_error("not an MCAP file (no Header record after the magic)");
        const auto [op, content, n] = record_at(8, "header");
        ByteReader in(content, n);
        in.fields(r_.profile, r_.library);
        return kRecordPrefix + n;
    }

    struct Rec {
        std::uint8_t op;
        const std::uint8_t* content;
        std::uint64_t n;
    };
    Rec record_at(std::uint64_t pos, const char* where) const {
        if (pos == f_.size()) throw Bad{pos, std::string("file ends in the ") + where + " (no further record)"};
        if (f_.size() - pos < kRecordPrefix)
            throw Bad{pos, std::string("truncated record header in the ") + where};
        ByteReader in(f_.data() + pos, kRecordPrefix);
        const std::uint8_t op = in.u8();
        const std::uint64_t n = in.u64();
        if (n > f_.size() - pos - kRecordPrefix)
            throw Bad{pos, op_name(op) + " record of " + std::to_string(n) + " bytes, only " +
                               std::to_string(f_.size() - pos - kRecordPrefix) + " left"};
        return {op, f_.data() + pos + kRecordPrefix, n};
    }

    void data_record(std::uint8_t op, ByteReader& in, std::uint64_t pos) {
        switch (static_cast<Op>(op)) {
            case Op::Schema: schema(in); break;
            case Op::Channel: channel(in); break;
            case Op::Message: message(in, pos); break;
            case Op::Chunk: chunk(in, pos); break;
            case Op::Metadata: {
                Metadata m;
                in.fields(m.name, m.entries);
                r_.metadata.push_back(std::move(m));
                break;
            }
            case Op::Attachment: attachment(in, pos); break;
            case Op::Header: throw Bad{pos, "a second Header record"};
            case Op::Footer: throw Bad{pos, "Footer before Data End"};
            default: break;  // message indexes, and records of future versions: skipped
        }
    }

    void schema(ByteReader& in) {
        Schema s;
        in.fields(s.id, s.name, s.encoding, s.data);
        r_.schemas[s.id] = std::move(s);
    }

    void channel(ByteReader& in) {
        Channel c;
        in.fields(c.id, c.schema_id, c.topic, c.message_encoding, c.metadata);
        r_.channels[c.id] = std::move(c);
    }

    void message(ByteReader& in, std::uint64_t pos) {
        MessageView m;
        in.fields(m.channel_id, m.sequence, m.log_time, m.publish_time);
        m.size = in.left();
        m.data = in.bytes(m.size);
        const auto c = r_.channels.find(m.channel_id);
        if (c == r_.channels.end())
            throw Bad{pos, "message on channel " + std::to_string(m.channel_id) + " before its Channel record"};
        m.channel = &c->second;
        const auto s = r_.schemas.find(c->second.schema_id);
        m.schema = s == r_.schemas.end() ? nullptr : &s->second;
        ++r_.messages;
        cb_(m);
    }

    void attachment(ByteReader& in, std::uint64_t pos) {
        Attachment a;
        in.fields(a.log_time, a.create_time, a.name, a.media_type);
        const std::uint64_t n = in.u64();
        const std::uint8_t* d = in.bytes(n);
        a.data.assign(reinterpret_cast<const char*>(d), n);
        const std::size_t crc_covered = in.pos();
        const std::uint32_t crc = in.u32();
        const std::uint32_t actual = crc32_update(0, f_.data() + pos + kRecordPrefix, crc_covered);
        if (crc != 0 && crc != actual) throw Bad{pos, "attachment '" + a.name + "': CRC-32 mismatch"};
        r_.attachments.push_back(std::move(a));
    }

    void chunk(ByteReader& in, std::uint64_t pos) {
        in.u64();  // message start time
        in.u64();  // message end time
        const std::uint64_t usize = in.u64();
        const std::uint32_t ucrc = in.u32();
        const std::string compression = in.str();
        const std::uint64_t csize = in.u64();
        const std::uint8_t* records = in.bytes(csize);
        const std::uint8_t* plain = records;
        if (usize > (std::uint64_t{1} << 32)) throw Bad{pos, "chunk of " + std::to_string(usize) + " bytes (limit 4 GiB)"};
        if (compression == "zstd") {
            buf_.resize(usize);
            const std::size_t got = ZSTD_decompress(buf_.data(), buf_.size(), records, csize);
            if (ZSTD_isError(got)) throw Bad{pos, std::string("chunk: zstd: ") + ZSTD_getErrorName(got)};
            if (got != usize) throw Bad{pos, "chunk: " + std::to_string(got) + " bytes decompressed, " +
                                                  std::to_string(usize) + " announced"};
            plain = buf_.data();
        } else if (!compression.empty()) {
            throw Bad{pos, "chunk compression '" + compression + "' is not supported (zstd, none)"};
        } else if (csize != usize) {
            throw Bad{pos, "uncompressed chunk of " + std::to_string(csize) + " bytes announces " +
                               std::to_string(usize)};
        }
        if (ucrc != 0 && crc32_update(0, plain, usize) != ucrc) throw Bad{pos, "chunk: CRC-32 of its records differs"};
        std::uint64_t at = 0;
        while (at < usize) {
            if (usize - at < kRecordPrefix) throw Bad{pos, "chunk: truncated record inside"};
            ByteReader h(plain + at, kRecordPrefix);
            const std::uint8_t op = h.u8();
            const std::uint64_t n = h.u64();
            if (n > usize - at - kRecordPrefix) throw Bad{pos, "chunk: record runs past the chunk's end"};
            ByteReader rec(plain + at + kRecordPrefix, n);
            try {
                if (op == static_cast<std::uint8_t>(Op::Schema)) schema(rec);
                else if (op == static_cast<std::uint8_t>(Op::Channel)) channel(rec);
                else if (op == static_cast<std::uint8_t>(Op::Message)) message(rec, pos);
            } catch (const std::out_of_range& e) {
                throw Bad{pos, "chunk: " + op_name(op) + " record: " + e.what()};
            }
            at += kRecordPrefix + n;
        }
        ++r_.chunks;
    }

    void summary(std::uint64_t pos) {
        const std::uint64_t summary_start = pos;
        while (true) {
            const auto [op, content, n] = record_at(pos, "summary");
            ByteReader in(content, n);
            try {
                if (op == static_cast<std::uint8_t>(Op::Footer)) {
                    footer(pos, summary_start, true);
                    return;
                }
                if (op == static_cast<std::uint8_t>(Op::Statistics)) statistics(in);
                if (op == static_cast<std::uint8_t>(Op::ChunkIndex)) chunk_index(in);
            } catch (const std::out_of_range& e) {
                throw Bad{pos, op_name(op) + " record: " + e.what()};
            }
            pos += kRecordPrefix + n;
        }
    }

    // A map<uint16 channel id, uint64> field (Statistics.channel_message_counts, ChunkIndex.message_index_offsets).
    template <class Map>
    static void read_channel_map(ByteReader& in, Map& out) {
        const std::uint32_t n = in.u32();
        ByteReader m(in.bytes(n), n);
        while (m.left() > 0) {
            const std::uint16_t ch = m.u16();
            out[ch] = m.u64();
        }
    }

    void statistics(ByteReader& in) {
        Statistics s;
        in.fields(s.message_count, s.schema_count, s.channel_count, s.attachment_count, s.metadata_count,
                  s.chunk_count, s.message_start_time, s.message_end_time);
        read_channel_map(in, s.channel_message_counts);
        r_.statistics = s;
    }

    void chunk_index(ByteReader& in) {
        ChunkIndex c;
        in.fields(c.message_start_time, c.message_end_time, c.chunk_start_offset, c.chunk_length);
        read_channel_map(in, c.message_index_offsets);
        in.fields(c.message_index_length, c.compression, c.compressed_size, c.uncompressed_size);
        r_.chunk_indexes.push_back(std::move(c));
    }

    void footer(std::uint64_t pos, std::uint64_t summary_start, bool count_messages) {
        ByteReader fin(f_.data() + pos + kRecordPrefix, kFooterContent);
        const std::uint64_t s_start = fin.u64();
        fin.u64();  // summary offset start
        const std::uint32_t crc = fin.u32();
        if (pos + kRecordPrefix + kFooterContent + 8 != f_.size() ||
            std::memcmp(f_.data() + f_.size() - 8, kMagic, 8) != 0)
            throw Bad{pos, "no closing magic right after the Footer"};
        if (s_start != 0 && s_start != summary_start)
            throw Bad{pos, "Footer.summary_start " + std::to_string(s_start) + " is not the summary's start " +
                               std::to_string(summary_start)};
        if (s_start != 0 && crc != 0) {
            const std::uint32_t actual = crc32_update(0, f_.data() + s_start, pos + kRecordPrefix + 16 - s_start);
            if (actual != crc) throw Bad{pos, "summary CRC-32 " + hex(actual) + " differs from the Footer's " + hex(crc)};
        }
        if (count_messages && r_.statistics && r_.statistics->message_count != r_.messages)
            throw Bad{pos, "Statistics count " + std::to_string(r_.statistics->message_count) + " messages, the data " +
                               "section holds " + std::to_string(r_.messages)};
    }

    const std::vector<std::uint8_t>& f_;
    ReadResult& r_;
    const std::function<void(const MessageView&)>& cb_;
    std::vector<std::uint8_t> buf_;
};

std::vector<std::uint8_t> load(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw std::runtime_error(file.string() + ": cannot read");
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw std::runtime_error(file.string() + ": read error");
    return bytes;
}

}  // namespace

namespace {

// Loads the file and runs the scanner (the whole file, or only footer and summary); a cut or damaged file ends the
// scan with `complete = false` and the byte it stopped at; anything else throws naming the file.
ReadResult scan_file(const std::filesystem::path& file, const std::function<void(const MessageView&)>& on_message,
                     bool summary_only) {
    const std::vector<std::uint8_t> bytes = load(file);
    ReadResult r;
    Scanner s(bytes, r, on_message);
    try {
        if (summary_only) {
            if (bytes.size() < 8 || std::memcmp(bytes.data(), kMagic, 8) != 0)
                throw std::runtime_error("not an MCAP file (magic)");
            s.run_summary();
        } else {
            s.run();
        }
    } catch (const Bad& b) {
        r.complete = false;
        r.problem = "at byte " + std::to_string(b.at) + " of " + std::to_string(bytes.size()) + ": " + b.what;
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(file.string() + ": " + e.what());
    }
    return r;
}

}  // namespace

ReadResult read_summary(const std::filesystem::path& file) {
    return scan_file(file, [](const MessageView&) {}, true);
}

ReadResult read(const std::filesystem::path& file, const std::function<void(const MessageView&)>& on_message) {
    return scan_file(file, on_message, false);
}

}  // namespace gdnav::io::mcap
