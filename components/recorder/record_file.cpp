#include "record_file.hpp"

#include <yaml-cpp/yaml.h>

#include <cstring>
#include <stdexcept>

#include "runtime/topic_types.hpp"

namespace gdnav::recorder {

namespace fs = std::filesystem;

namespace {
constexpr std::size_t kHeaderBytes = 12;
constexpr std::uint32_t kMaxSampleBytes = 1u << 20;  // gdnav samples are < 1 KiB; anything larger is corruption

std::uint64_t read_le(const std::uint8_t* p, int bytes) {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i) v |= static_cast<std::uint64_t>(p[i]) << (8 * i);
    return v;
}

struct SampleDeleter {
    const runtime::MessageOps* ops;
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

std::string digest_hex(std::uint64_t digest) {
    char hex[20];
    std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(digest));
    return hex;
}

std::string record_file_name(const std::string& topic) {
    std::string s;
    for (char c : topic) s += (c == '/') ? std::string("__") : std::string(1, c);
    return s + ".cdr";
}

std::string resolve_topic(const std::string& name) {
    if (runtime::find_topic(name)) return name;
    const std::string full = "gdnav/" + name;
    if (name.find('/') == std::string::npos && runtime::find_topic(full)) return full;
    return {};
}

std::string known_topics_list() {
    std::string known;
    for (const auto& k : runtime::known_topics()) known += (known.empty() ? "" : ", ") + k;
    return known;
}

// ------------------------------------------------------------------------------------------------ SampleDecoder
SampleDecoder::SampleDecoder(const runtime::MessageOps& ops) : type_(ops.make_type()) {}

SampleDecoder::~SampleDecoder() = default;

bool SampleDecoder::decode(const std::uint8_t* bytes, std::uint32_t n, void* sample) {
    if (payload_.max_size < n) payload_.reserve(n);
    std::memcpy(payload_.data, bytes, n);
    payload_.length = n;
    payload_.pos = 0;
    try {
        return type_->deserialize(&payload_, sample);
    } catch (const std::exception&) {
        return false;  // Fast CDR throws on payloads shorter than the type
    }
}

// ------------------------------------------------------------------------------------------------ reading
TopicRecord read_topic_record(const fs::path& dir, const std::string& topic) {
    TopicRecord r;
    r.topic = topic;
    r.ops = runtime::find_topic(topic);
    if (!r.ops) throw std::runtime_error("unknown topic '" + topic + "' (known: " + known_topics_list() + ")");
    r.file = dir / record_file_name(topic);
    std::error_code ec;
    if (!fs::is_regular_file(r.file, ec)) throw std::runtime_error(r.file.string() + ": missing (no record of " + topic + ")");
    std::ifstream in(r.file, std::ios::binary);
    if (!in) throw std::runtime_error(r.file.string() + ": cannot read");
    r.bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    if (in.bad()) throw std::runtime_error(r.file.string() + ": read error");

    SampleDecoder decoder(*r.ops);
    std::unique_ptr<void, SampleDeleter> sample(r.ops->create(), SampleDeleter{r.ops});
    std::size_t pos = 0;
    while (pos < r.bytes.size()) {
        const std::size_t index = r.entries.size();
        auto fail = [&](const std::string& what) {
            throw std::runtime_error(r.file.string() + ": record " + std::to_string(index) + " (byte " +
                                     std::to_string(pos) + "): " + what);
        };
        if (r.bytes.size() - pos < kHeaderBytes) fail("truncated record header");
        const std::uint64_t step = read_le(&r.bytes[pos], 8);
        const auto n = static_cast<std::uint32_t>(read_le(&r.bytes[pos + 8], 4));
        if (n == 0 || n > kMaxSampleBytes) fail("implausible sample size " + std::to_string(n) + " bytes");
        if (r.bytes.size() - pos - kHeaderBytes < n)
            fail("truncated sample (" + std::to_string(n) + " bytes announced, " +
                 std::to_string(r.bytes.size() - pos - kHeaderBytes) + " left)");
        if (!r.entries.empty() && step <= r.entries.back().step)
            fail("step " + std::to_string(step) + " after step " + std::to_string(r.entries.back().step) +
                 " (steps must increase)");
        if (!decoder.decode(&r.bytes[pos + kHeaderBytes], n, sample.get()))
            fail("the payload is not a " + std::string(r.ops->type_name) + " sample");
        const std::uint64_t stamped = r.ops->step_of(sample.get());
        if (stamped != UINT64_MAX && stamped != step)
            fail("sample stamped step " + std::to_string(stamped) + " in the record of step " + std::to_string(step));
        r.entries.push_back({step, pos + kHeaderBytes, n});
        pos += kHeaderBytes + n;
    }
    r.digest = fnv1a(kFnvBasis, r.bytes.data(), r.bytes.size());
    return r;
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

// ------------------------------------------------------------------------------------------------ writing
RecordWriter::RecordWriter(const fs::path& dir, const std::string& topic)
    : topic_(topic), ops_(runtime::find_topic(topic)), path_(dir / record_file_name(topic)) {
    if (!ops_) throw std::runtime_error("unknown topic '" + topic + "' (known: " + known_topics_list() + ")");
    fs::create_directories(dir);
    file_.open(path_, std::ios::binary | std::ios::trunc);
    if (!file_) throw std::runtime_error(path_.string() + ": cannot write");
}

void RecordWriter::append(std::uint64_t step, const void* sample) {
    if (samples_ > 0 && step <= last_step_)
        throw std::logic_error("RecordWriter: steps must increase (" + path_.string() + ")");
    ops_->serialize(sample, buffer_);
    std::uint8_t head[kHeaderBytes];
    for (int i = 0; i < 8; ++i) head[i] = static_cast<std::uint8_t>(step >> (8 * i));
    const auto n = static_cast<std::uint32_t>(buffer_.size());
    for (int i = 0; i < 4; ++i) head[8 + i] = static_cast<std::uint8_t>(n >> (8 * i));
    file_.write(reinterpret_cast<const char*>(head), sizeof(head));
    file_.write(reinterpret_cast<const char*>(buffer_.data()), static_cast<std::streamsize>(n));
    if (!file_) throw std::runtime_error(path_.string() + ": write error");
    digest_ = fnv1a(fnv1a(digest_, head, sizeof(head)), buffer_.data(), n);
    ++samples_;
    last_step_ = step;
}

void RecordWriter::close() {
    file_.close();
    if (file_.fail()) throw std::runtime_error(path_.string() + ": write error");
}

void write_digest_file(const fs::path& dir, const std::vector<const RecordWriter*>& writers, bool complete,
                       const std::map<std::string, std::uint64_t>& lost_at) {
    std::ofstream d(dir / "digest.yaml");
    d << "complete: " << (complete ? "true" : "false") << "\ntopics:\n";
    for (const RecordWriter* w : writers) {
        d << "  " << w->topic() << ": {samples: " << w->samples() << ", last_step: " << w->last_step()
          << ", digest: \"" << digest_hex(w->digest()) << "\"";
        if (auto it = lost_at.find(w->topic()); it != lost_at.end()) d << ", lost_at_step: " << it->second;
        d << "}\n";
    }
    if (!d) throw std::runtime_error((dir / "digest.yaml").string() + ": write error");
}

}  // namespace gdnav::recorder
