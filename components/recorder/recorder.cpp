#include "recorder.hpp"

#include <filesystem>

#include <spdlog/spdlog.h>

#include "runtime/registry.hpp"
#include "runtime/topic_types.hpp"

namespace gdnav::recorder {

namespace {
std::uint64_t fnv(std::uint64_t h, const std::uint8_t* p, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
        h ^= p[i];
        h *= 0x100000001b3ULL;
    }
    return h;
}
std::string file_name(const std::string& topic) {
    std::string s;
    for (char c : topic) s += (c == '/') ? std::string("__") : std::string(1, c);
    return s;
}
}  // namespace

void Recorder::configure(const config::Config& cfg, const runtime::RunInfo& run, rnd::Stream&) {
    const auto topics = cfg.get_strings("topics");
    decimation_ = static_cast<std::uint64_t>(cfg.get_int("decimation", 1, 1, 100000));
    if (topics.empty()) cfg.fail("topics", "at least one topic is required");
    for (const auto& t : topics) {
        const runtime::MessageOps* ops = runtime::find_topic(t);
        if (!ops) {
            std::string known;
            for (const auto& k : runtime::known_topics()) known += (known.empty() ? "" : ", ") + k;
            cfg.fail("topics", "unknown topic '" + t + "' (known: " + known + ")");
        }
        auto tr = std::make_unique<Track>();
        tr->input = std::make_unique<runtime::InputBase>(*this, t, runtime::Lag::Same, *ops);
        tracks_.push_back(std::move(tr));
    }
    dir_ = run.out_dir.empty() ? std::string() : (std::filesystem::path(run.out_dir) / "record").string();
}

void Recorder::step(const runtime::StepContext& ctx) {
    if (dir_.empty()) return;
    if (!tracks_.empty() && !tracks_.front()->file.is_open()) {
        std::filesystem::create_directories(dir_);
        for (auto& tr : tracks_)
            tr->file.open(std::filesystem::path(dir_) / (file_name(tr->input->topic()) + ".cdr"), std::ios::binary);
    }
    if (ctx.k % decimation_ != 0) return;
    for (auto& tr : tracks_) {
        if (!tr->input->available()) {
            if (tr->input->lost() && !tr->lost_reported) {
                tr->lost_reported = true;
                tr->lost_at = ctx.k;
            }
            continue;
        }
        tr->input->ops().serialize(tr->input->data_ptr(), buffer_);
        std::uint8_t head[12];
        for (int i = 0; i < 8; ++i) head[i] = static_cast<std::uint8_t>(ctx.k >> (8 * i));
        const auto n = static_cast<std::uint32_t>(buffer_.size());
        for (int i = 0; i < 4; ++i) head[8 + i] = static_cast<std::uint8_t>(n >> (8 * i));
        tr->file.write(reinterpret_cast<const char*>(head), sizeof(head));
        tr->file.write(reinterpret_cast<const char*>(buffer_.data()), static_cast<std::streamsize>(n));
        tr->digest = fnv(fnv(tr->digest, head, sizeof(head)), buffer_.data(), n);
        ++tr->samples;
        tr->last_step = ctx.k;
    }
}

void Recorder::finish(bool completed) {
    if (finished_ || dir_.empty()) return;
    finished_ = true;
    std::filesystem::create_directories(dir_);
    for (auto& tr : tracks_) tr->file.close();
    std::ofstream d(std::filesystem::path(dir_) / "digest.yaml");
    d << "complete: " << (completed ? "true" : "false") << "\ntopics:\n";
    for (auto& tr : tracks_) {
        char hex[20];
        std::snprintf(hex, sizeof(hex), "%016llx", static_cast<unsigned long long>(tr->digest));
        d << "  " << tr->input->topic() << ": {samples: " << tr->samples << ", last_step: " << tr->last_step
          << ", digest: \"" << hex << "\"";
        if (tr->lost_reported) d << ", lost_at_step: " << tr->lost_at;
        d << "}\n";
    }
    spdlog::debug("recorder: wrote {}", dir_);
}

void register_recorder(runtime::ComponentRegistry& reg) {
    reg.add("recorder", "records topics to <out>/record (CDR per topic + digest.yaml)",
            [](const std::string& n) { return std::make_unique<Recorder>(n); });
}

}  // namespace gdnav::recorder
