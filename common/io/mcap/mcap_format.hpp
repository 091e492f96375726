#pragma once
// MCAP binary layout (https://mcap.dev/spec, major version 0): magic, record opcodes and the little-endian
// primitives (uint8/16/32/64, String = uint32 length + UTF-8, Bytes with uint32 or uint64 length, Map = uint32 byte
// length + entries). Every record is <opcode u8><content length u64><content>.
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace gdnav::io::mcap {

inline constexpr std::uint8_t kMagic[8] = {0x89, 'M', 'C', 'A', 'P', 0x30, '\r', '\n'};

// The well-known encodings (https://mcap.dev/spec/registry) of every gdnav channel, recorded (io/recording) or live
// (io/viewer, the Foxglove WebSocket bridge): messages in CDR with their encapsulation header, schemas in OMG IDL.
inline constexpr const char* kCdr = "cdr";
inline constexpr const char* kOmgIdl = "omgidl";

enum class Op : std::uint8_t {
    Header = 0x01,
    Footer = 0x02,
    Schema = 0x03,
    Channel = 0x04,
    Message = 0x05,
    Chunk = 0x06,
    MessageIndex = 0x07,
    ChunkIndex = 0x08,
    Attachment = 0x09,
    AttachmentIndex = 0x0A,
    Statistics = 0x0B,
    Metadata = 0x0C,
    MetadataIndex = 0x0D,
    SummaryOffset = 0x0E,
    DataEnd = 0x0F,
};

inline constexpr std::size_t kRecordPrefix = 9;  // opcode + content length
inline constexpr std::size_t kFooterContent = 20;  // summary_start, summary_offset_start, summary_crc

using StringMap = std::map<std::string, std::string>;

// A record's fields are written and read in order, each in the wire form of its C++ type, so a record's layout is
// the types of its fields: uint8/16/32/64 as such, std::string as String, StringMap as Map. Any other type (an int,
// a uint16 meant as uint32 on the wire) does not compile: say the wire type with a cast.
template <class T>
inline constexpr bool kWireType = std::is_same_v<T, std::uint8_t> || std::is_same_v<T, std::uint16_t> ||
                                  std::is_same_v<T, std::uint32_t> || std::is_same_v<T, std::uint64_t> ||
                                  std::is_same_v<T, std::string> || std::is_same_v<T, StringMap>;

// Appends little-endian fields to a byte buffer.
class ByteWriter {
public:
    explicit ByteWriter(std::vector<std::uint8_t>& out) : out_(out) {}
    void u8(std::uint8_t v) { out_.push_back(v); }
    void u16(std::uint16_t v) { le(v, 2); }
    void u32(std::uint32_t v) { le(v, 4); }
    void u64(std::uint64_t v) { le(v, 8); }
    void bytes(const std::uint8_t* p, std::size_t n) { out_.insert(out_.end(), p, p + n); }
    void str(const std::string& s) {
        u32(static_cast<std::uint32_t>(s.size()));
        bytes(reinterpret_cast<const std::uint8_t*>(s.data()), s.size());
    }
    void map(const StringMap& m) {
        std::uint32_t n = 0;
        for (const auto& [k, v] : m) n += static_cast<std::uint32_t>(8 + k.size() + v.size());
        u32(n);
        for (const auto& [k, v] : m) {
            str(k);
            str(v);
        }
    }
    // A map<uint16 channel id, uint64> field (Statistics.channel_message_counts, ChunkIndex.message_index_offsets).
    void channel_map(const std::map<std::uint16_t, std::uint64_t>& m) {
        u32(static_cast<std::uint32_t>(m.size() * 10));
        for (const auto& [ch, v] : m) {
            u16(ch);
            u64(v);
        }
    }
    // Starts a record; returns the position of its length field, which end_record() fills in.
    std::size_t begin_record(Op op) {
        u8(static_cast<std::uint8_t>(op));
        const std::size_t at = out_.size();
        u64(0);
        return at;
    }
    void end_record(std::size_t length_at) {
        const std::uint64_t n = out_.size() - length_at - 8;
        for (int i = 0; i < 8; ++i) out_[length_at + i] = static_cast<std::uint8_t>(n >> (8 * i));
    }
    [[nodiscard]] std::size_t size() const { return out_.size(); }
    // The fields in order, each in its type's wire form (kWireType).
    template <class... T>
    void fields(const T&... v) {
        (put(v), ...);
    }

private:
    template <class T>
    void put(const T& v) {
        static_assert(kWireType<T>, "not a wire type");
        if constexpr (std::is_same_v<T, std::uint8_t>) u8(v);
        else if constexpr (std::is_same_v<T, std::uint16_t>) u16(v);
        else if constexpr (std::is_same_v<T, std::uint32_t>) u32(v);
        else if constexpr (std::is_same_v<T, std::uint64_t>) u64(v);
        else if constexpr (std::is_same_v<T, std::string>) str(v);
        else map(v);
    }
    void le(std::uint64_t v, int n) {
        for (int i = 0; i < n; ++i) out_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    std::vector<std::uint8_t>& out_;
};

// Reads little-endian fields from a byte range; throws std::out_of_range past its end.
class ByteReader {
public:
    ByteReader(const std::uint8_t* p, std::size_t n) : p_(p), n_(n) {}
    std::uint8_t u8() { return static_cast<std::uint8_t>(le(1)); }
    std::uint16_t u16() { return static_cast<std::uint16_t>(le(2)); }
    std::uint32_t u32() { return static_cast<std::uint32_t>(le(4)); }
    std::uint64_t u64() { return le(8); }
    const std::uint8_t* bytes(std::uint64_t n) {
        need(n);
        const std::uint8_t* at = p_ + pos_;
        pos_ += static_cast<std::size_t>(n);
        return at;
    }
    std::string str() {
        const std::uint32_t n = u32();
        const std::uint8_t* s = bytes(n);
        return {reinterpret_cast<const char*>(s), n};
    }
    StringMap map() {
        const std::uint32_t n = u32();
        ByteReader sub(bytes(n), n);
        StringMap m;
        while (sub.left() > 0) {
            std::string k = sub.str();
            m[k] = sub.str();
        }
        return m;
    }
    [[nodiscard]] std::size_t left() const { return n_ - pos_; }
    [[nodiscard]] std::size_t pos() const { return pos_; }
    // Reads the fields in order, each in its type's wire form (kWireType).
    template <class... T>
    void fields(T&... v) {
        (get(v), ...);
    }

private:
    template <class T>
    void get(T& v) {
        static_assert(kWireType<T>, "not a wire type");
        if constexpr (std::is_same_v<T, std::uint8_t>) v = u8();
        else if constexpr (std::is_same_v<T, std::uint16_t>) v = u16();
        else if constexpr (std::is_same_v<T, std::uint32_t>) v = u32();
        else if constexpr (std::is_same_v<T, std::uint64_t>) v = u64();
        else if constexpr (std::is_same_v<T, std::string>) v = str();
        else v = map();
    }
    void need(std::uint64_t n) const {
        if (n > n_ - pos_) throw std::out_of_range("field runs past the end of its record");
    }
    std::uint64_t le(int n) {
        need(static_cast<std::uint64_t>(n));
        std::uint64_t v = 0;
        for (int i = 0; i < n; ++i) v |= static_cast<std::uint64_t>(p_[pos_ + i]) << (8 * i);
        pos_ += static_cast<std::size_t>(n);
        return v;
    }
    const std::uint8_t* p_;
    std::size_t n_;
    std::size_t pos_{0};
};

}  // namespace gdnav::io::mcap
