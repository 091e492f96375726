// common/io/mcap against the MCAP specification (https://mcap.dev/spec): CRC-32, a written file read back (records,
// statistics, chunk and message indexes checked byte by byte), and files cut short or damaged.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <string>
#include <vector>

#include "io/mcap/crc32.hpp"
#include "io/mcap/mcap_format.hpp"
#include "io/mcap/mcap_reader.hpp"
#include "io/mcap/mcap_writer.hpp"

namespace fs = std::filesystem;
using namespace gdnav::io::mcap;

namespace {

fs::path temp_dir() { return fs::temp_directory_path() / ("gdnav-mcap-test-" + std::to_string(::getpid())); }

fs::path temp_file(const std::string& name) {
    fs::create_directories(temp_dir());
    return temp_dir() / name;
}

// Removes the test files at the end.
class TempFiles : public ::testing::Environment {
public:
    void TearDown() override { fs::remove_all(temp_dir()); }
};
const auto* const kTempFiles = ::testing::AddGlobalTestEnvironment(new TempFiles);

std::vector<std::uint8_t> bytes_of(const fs::path& f) {
    std::ifstream in(f, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& f, const std::vector<std::uint8_t>& b, std::size_t n) {
    std::ofstream out(f, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(n));
}

// The payload of message i on channel c: varied bytes and lengths (so that chunks compress differently).
std::vector<std::uint8_t> payload(std::uint32_t i, std::uint16_t c) {
    std::vector<std::uint8_t> p(20 + (i * 7 + c) % 50);
    for (std::size_t k = 0; k < p.size(); ++k) p[k] = static_cast<std::uint8_t>((i * 31 + k * 17 + c * 101) & 0xFF);
    return p;
}

struct Got {
    std::uint16_t channel;
    std::uint32_t sequence;
    std::uint64_t log_time, publish_time;
    std::vector<std::uint8_t> data;
};

constexpr std::uint32_t kSteps = 600;

// Two channels of one schema and one of another; a message per channel and step; chunks of `chunk_bytes`.
fs::path write_sample_file(const std::string& name, const std::string& compression, std::size_t chunk_bytes) {
    const fs::path f = temp_file(name);
    Writer w(f, {"x-test", "gdnav mcap_test", compression, 3, chunk_bytes});
    const auto s1 = w.add_schema("test::A", "omgidl", "module test { struct A { double x; }; };");
    const auto s2 = w.add_schema("test::B", "omgidl", "module test { struct B { long y; }; };");
    const auto c0 = w.add_channel(s1, "a/0", "cdr", {{"k", "v"}});
    const auto c1 = w.add_channel(s1, "a/1", "cdr");
    const auto c2 = w.add_channel(s2, "b", "cdr");
    w.write_metadata("run", {{"seed", "7"}, {"name", "test"}});
    w.write_attachment("run.yaml", "application/yaml", 5, 6, "run: {seed: 7}\n");
    for (std::uint32_t i = 0; i < kSteps; ++i)
        for (std::uint16_t c : {c0, c1, c2}) {
            const auto p = payload(i, c);
            w.write_message(c, i, 1000ull * i, 1000ull * i + c, p.data(), p.size());
        }
    w.close();
    return f;
}

ReadResult read_all(const fs::path& f, std::vector<Got>& got) {
    return read(f, [&](const MessageView& m) {
        got.push_back({m.channel_id, m.sequence, m.log_time, m.publish_time, {m.data, m.data + m.size}});
    });
}

std::uint64_t le(const std::vector<std::uint8_t>& b, std::uint64_t at, int n) {
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= static_cast<std::uint64_t>(b.at(at + i)) << (8 * i);
    return v;
}

}  // namespace

TEST(McapCrc, IsTheIeeeCrc32) {
    const std::string s = "123456789";
    EXPECT_EQ(crc32_update(0, reinterpret_cast<const std::uint8_t*>(s.data()), s.size()), 0xCBF43926u);
    // Continued CRCs equal the CRC of the concatenation.
    const auto* p = reinterpret_cast<const std::uint8_t*>(s.data());
    EXPECT_EQ(crc32_update(crc32_update(0, p, 4), p + 4, 5), 0xCBF43926u);
    EXPECT_EQ(crc32_update(0, p, 0), 0u);
    // Long inputs (the eight-bytes-at-a-time path) against the bitwise definition, at every length and alignment.
    std::vector<std::uint8_t> b(300);
    for (std::size_t i = 0; i < b.size(); ++i) b[i] = static_cast<std::uint8_t>(i * 73 + 11);
    for (std::size_t start : {0u, 1u, 3u})
        for (std::size_t n = 0; n + start <= b.size(); n += 7) {
            std::uint32_t c = 0xFFFFFFFFu;
            for (std::size_t i = start; i < start + n; ++i) {
                c ^= b[i];
                for (int k = 0; k < 8; ++k) c = (c & 1u) ? (0xEDB88320u ^ (c >> 1)) : (c >> 1);
            }
            EXPECT_EQ(crc32_update(0, b.data() + start, n), c ^ 0xFFFFFFFFu) << start << " " << n;
        }
}

TEST(McapFile, WrittenFileReadsBackWithEveryRecord) {
    for (const std::string compression : {"zstd", ""}) {
        const fs::path f = write_sample_file("roundtrip" + compression + ".mcap", compression, 4096);
        const auto b = bytes_of(f);
        ASSERT_GE(b.size(), 16u);
        EXPECT_EQ(std::vector<std::uint8_t>(b.begin(), b.begin() + 8), std::vector<std::uint8_t>(kMagic, kMagic + 8));
        EXPECT_EQ(std::vector<std::uint8_t>(b.end() - 8, b.end()), std::vector<std::uint8_t>(kMagic, kMagic + 8));
        std::vector<Got> got;
        const ReadResult r = read_all(f, got);
        EXPECT_TRUE(r.complete) << r.problem;
        EXPECT_EQ(r.profile, "x-test");
        EXPECT_EQ(r.library, "gdnav mcap_test");
        ASSERT_EQ(r.schemas.size(), 2u);
        EXPECT_EQ(r.schemas.at(1).name, "test::A");
        EXPECT_EQ(r.schemas.at(2).data, "module test { struct B { long y; }; };");
        ASSERT_EQ(r.channels.size(), 3u);
        EXPECT_EQ(r.channels.at(0).topic, "a/0");
        EXPECT_EQ(r.channels.at(0).metadata.at("k"), "v");
        EXPECT_EQ(r.channels.at(2).schema_id, 2);
        ASSERT_EQ(got.size(), 3u * kSteps);
        for (std::size_t n = 0; n < got.size(); ++n) {
            const auto i = static_cast<std::uint32_t>(n / 3);
            const auto c = static_cast<std::uint16_t>(n % 3);
            EXPECT_EQ(got[n].channel, c);
            EXPECT_EQ(got[n].sequence, i);
            EXPECT_EQ(got[n].log_time, 1000ull * i);
            EXPECT_EQ(got[n].publish_time, 1000ull * i + c);
            EXPECT_EQ(got[n].data, payload(i, c)) << n;
        }
        ASSERT_EQ(r.metadata.size(), 1u);
        EXPECT_EQ(r.metadata[0].entries.at("seed"), "7");
        ASSERT_EQ(r.attachments.size(), 1u);
        EXPECT_EQ(r.attachments[0].data, "run: {seed: 7}\n");
        EXPECT_EQ(r.attachments[0].create_time, 6u);
        ASSERT_TRUE(r.statistics);
        EXPECT_EQ(r.statistics->message_count, 3u * kSteps);
        EXPECT_EQ(r.statistics->channel_count, 3u);
        EXPECT_EQ(r.statistics->schema_count, 2u);
        EXPECT_EQ(r.statistics->chunk_count, r.chunks);
        EXPECT_EQ(r.statistics->message_end_time, 1000ull * (kSteps - 1));
        EXPECT_EQ(r.statistics->channel_message_counts.at(2), kSteps);
        EXPECT_GT(r.chunks, 5u);  // 4 KiB chunks
        if (compression == "zstd") {
            EXPECT_LT(b.size(), 3u * kSteps * 50u);  // compressed below the raw message bytes
        }
    }
}

TEST(McapFile, SummaryIndexesPointAtTheirChunksAndMessages) {
    const fs::path f = write_sample_file("index.mcap", "", 4096);  // uncompressed: message offsets checkable in place
    const auto b = bytes_of(f);
    const ReadResult s = read_summary(f);
    ASSERT_TRUE(s.complete) << s.problem;
    ASSERT_TRUE(s.statistics);
    EXPECT_EQ(s.channels.size(), 3u);
    EXPECT_EQ(s.schemas.size(), 2u);
    ASSERT_EQ(s.chunk_indexes.size(), s.statistics->chunk_count);
    std::uint64_t indexed = 0, previous_end = 0;
    for (const ChunkIndex& c : s.chunk_indexes) {
        EXPECT_EQ(b.at(c.chunk_start_offset), static_cast<std::uint8_t>(Op::Chunk));
        EXPECT_EQ(le(b, c.chunk_start_offset + 1, 8) + kRecordPrefix, c.chunk_length);
        EXPECT_EQ(le(b, c.chunk_start_offset + 9, 8), c.message_start_time);
        EXPECT_GE(c.message_start_time, previous_end);
        previous_end = c.message_end_time;
        // Chunk content: start, end, uncompressed size, crc, compression "", records length, then the records.
        const std::uint64_t records = c.chunk_start_offset + kRecordPrefix + 8 + 8 + 8 + 4 + 4 + 8;
        EXPECT_EQ(c.compression, "");
        EXPECT_EQ(c.compressed_size, c.uncompressed_size);
        std::uint64_t index_bytes = 0;
        for (const auto& [channel, offset] : c.message_index_offsets) {
            ASSERT_EQ(b.at(offset), static_cast<std::uint8_t>(Op::MessageIndex));
            const std::uint64_t len = le(b, offset + 1, 8);
            index_bytes += kRecordPrefix + len;
            EXPECT_EQ(le(b, offset + 9, 2), channel);
            const std::uint64_t entries = le(b, offset + 11, 4) / 16;
            for (std::uint64_t e = 0; e < entries; ++e) {
                const std::uint64_t t = le(b, offset + 15 + 16 * e, 8), off = le(b, offset + 23 + 16 * e, 8);
                const std::uint64_t m = records + off;  // a Message record with this channel and log time
                ASSERT_EQ(b.at(m), static_cast<std::uint8_t>(Op::Message));
                EXPECT_EQ(le(b, m + 9, 2), channel);
                EXPECT_EQ(le(b, m + 15, 8), t);
                ++indexed;
            }
        }
        EXPECT_EQ(index_bytes, c.message_index_length);
    }
    EXPECT_EQ(indexed, 3u * kSteps);
}

TEST(McapFile, FileCutAnywhereKeepsEveryCompleteChunk) {
    const fs::path f = write_sample_file("cut-source.mcap", "zstd", 4096);
    const auto b = bytes_of(f);
    std::vector<Got> all;
    const ReadResult full = read_all(f, all);
    ASSERT_TRUE(full.complete);
    const ReadResult s = read_summary(f);
    ASSERT_GE(s.chunk_indexes.size(), 4u);
    const fs::path cut = temp_file("cut.mcap");
    std::uint64_t previous = 0;
    int cuts = 0;
    for (std::size_t n = 40; n < b.size(); n += 211) {
        write_bytes(cut, b, n);
        std::vector<Got> got;
        const ReadResult r = read_all(cut, got);
        ++cuts;
        EXPECT_FALSE(r.complete) << n;
        EXPECT_NE(r.problem.find("at byte"), std::string::npos) << r.problem;
        EXPECT_LE(r.readable_bytes, n);
        // What was read is the start of the whole file's messages, whole chunks at a time, never less than before.
        ASSERT_LE(got.size(), all.size());
        for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i].data, all[i].data);
        EXPECT_GE(got.size(), previous);
        previous = got.size();
        if (n >= s.chunk_indexes[0].chunk_start_offset) {
            EXPECT_EQ(r.channels.size(), 3u);  // all written before the first chunk
        }
    }
    EXPECT_GT(cuts, 20);
    EXPECT_EQ(previous, all.size());  // cut in the summary: every message is still there
    // Cut right after the 3rd chunk's message indexes: exactly the messages of 3 chunks.
    const ChunkIndex& c3 = s.chunk_indexes[3];
    write_bytes(cut, b, c3.chunk_start_offset);
    std::vector<Got> got;
    const ReadResult r = read_all(cut, got);
    EXPECT_EQ(r.chunks, 3u);
    EXPECT_NE(r.problem.find("file ends in the data section"), std::string::npos) << r.problem;
    EXPECT_GT(got.size(), 0u);
    EXPECT_EQ(got.back().log_time, s.chunk_indexes[2].message_end_time);
    const ReadResult cs = read_summary(cut);
    EXPECT_FALSE(cs.complete);
    EXPECT_NE(cs.problem.find("no closing magic"), std::string::npos) << cs.problem;
}

TEST(McapFile, UnclosedWriterLeavesTheChunksWrittenSoFar) {
    // A writer still open (its process killed) has written every full chunk and flushed it.
    const fs::path f = temp_file("open.mcap");
    {
        Writer w(f, {"", "test", "zstd", 3, 2048});
        const auto s = w.add_schema("test::A", "omgidl", "module test { struct A { double x; }; };");
        const auto c = w.add_channel(s, "a", "cdr");
        for (std::uint32_t i = 0; i < 500; ++i) {
            const auto p = payload(i, 0);
            w.write_message(c, i, i, i, p.data(), p.size());
        }
        const fs::path copy = temp_file("open-copy.mcap");
        fs::copy_file(f, copy, fs::copy_options::overwrite_existing);
        std::vector<Got> got;
        const ReadResult r = read_all(copy, got);
        EXPECT_FALSE(r.complete);
        EXPECT_GT(got.size(), 300u);
        EXPECT_LT(got.size(), 500u);
        for (std::size_t i = 0; i < got.size(); ++i) EXPECT_EQ(got[i].sequence, i);
    }
}

TEST(McapFile, DamagedChunkIsReportedAndEarlierChunksStayReadable) {
    const fs::path f = write_sample_file("damaged-source.mcap", "", 4096);
    auto b = bytes_of(f);
    const ReadResult s = read_summary(f);
    ASSERT_GE(s.chunk_indexes.size(), 3u);
    b.at(s.chunk_indexes[2].chunk_start_offset + 120) ^= 0x40;  // inside the 3rd chunk's records
    const fs::path damaged = temp_file("damaged.mcap");
    write_bytes(damaged, b, b.size());
    std::vector<Got> got;
    const ReadResult r = read_all(damaged, got);
    EXPECT_FALSE(r.complete);
    EXPECT_NE(r.problem.find("CRC-32"), std::string::npos) << r.problem;
    EXPECT_EQ(r.chunks, 2u);
    EXPECT_EQ(got.back().log_time, s.chunk_indexes[1].message_end_time);
}

TEST(McapFile, NotAnMcapFileThrows) {
    const fs::path f = temp_file("not.mcap");
    std::ofstream(f) << "hello, this is not an MCAP file";
    EXPECT_THROW(read(f, [](const MessageView&) {}), std::runtime_error);
    EXPECT_THROW(read(temp_file("missing.mcap"), [](const MessageView&) {}), std::runtime_error);
}
