#include "recorder.hpp"

#include <filesystem>

#include <spdlog/spdlog.h>

#include "runtime/registry.hpp"
#include "runtime/topic_types.hpp"

namespace gdnav::recorder {


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

void Recorder::open_files() {
    for (auto& tr : tracks_)
        if (!tr->writer) tr->writer = std::make_unique<RecordWriter>(dir_, tr->input->topic());
}

void Recorder::step(const runtime::StepContext& ctx) {
    if (dir_.empty()) return;
    if (!tracks_.empty() && !tracks_.front()->writer) open_files();
    if (ctx.k % decimation_ != 0) return;
    for (auto& tr : tracks_) {
        if (!tr->input->available()) {
            if (tr->input->lost() && !tr->lost_reported) {
                tr->lost_reported = true;
                tr->lost_at = ctx.k;
            }
            continue;
        }
        tr->writer->append(ctx.k, tr->input->data_ptr());
    }
}

void Recorder::finish(bool completed) {
    if (finished_ || dir_.empty()) return;
    finished_ = true;
    open_files();  // a run that ended before its first step still gets (empty) files and a digest
    std::vector<const RecordWriter*> writers;
    std::map<std::string, std::uint64_t> lost_at;
    for (auto& tr : tracks_) {
        tr->writer->close();
        writers.push_back(tr->writer.get());
        if (tr->lost_reported) lost_at[tr->input->topic()] = tr->lost_at;
    }
    write_digest_file(dir_, writers, completed, lost_at);
    spdlog::debug("recorder: wrote {}", dir_);
}

void register_recorder(runtime::ComponentRegistry& reg) {
    reg.add("recorder", "records topics to <out>/record (CDR per topic + digest.yaml)",
            [](const std::string& n) { return std::make_unique<Recorder>(n); });
}

}  // namespace gdnav::recorder
