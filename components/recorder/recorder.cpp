#include "recorder.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <spdlog/spdlog.h>

#include "io/recording/run_metadata.hpp"
#include "framework/registry.hpp"
#include "framework/topic_types.hpp"

namespace gdnav::recorder {


void Recorder::configure(const config::Config& cfg, const framework::RunInfo& run, rnd::Stream&) {
    const auto topics = cfg.get_strings("topics");
    decimation_ = static_cast<std::uint64_t>(cfg.get_int("decimation", 1, 1, 100000));
    chunk_bytes_ = static_cast<std::size_t>(cfg.get_int("chunk_kib", 1024, 1, 65536)) * 1024;
    const bool with_viewer = cfg.get_bool("viewer", false);
    const auto viewer_decimation = static_cast<std::uint64_t>(cfg.get_int("viewer_decimation", 10, 1, 100000));
    if (topics.empty() && !with_viewer) cfg.fail("topics", "at least one topic is required (or viewer: true)");
    for (const auto& t : topics) {
        const msg::MessageOps* ops = framework::find_topic(t);
        if (!ops) {
            std::string known;
            for (const auto& k : framework::known_topics()) known += (known.empty() ? "" : ", ") + k;
            cfg.fail("topics", "unknown topic '" + t + "' (known: " + known + ")");
        }
        auto tr = std::make_unique<Track>();
        tr->input = std::make_unique<framework::InputBase>(*this, t, framework::Lag::Same, *ops);
        tracks_.push_back(std::move(tr));
    }
    if (with_viewer)
        viewer_ = std::make_unique<io::viewer::ViewerChannels>(*this, io::viewer::ViewerOptions{viewer_decimation});
    dir_ = run.out_dir.empty() ? std::string() : (std::filesystem::path(run.out_dir) / "record").string();
    run_ = run;
}

void Recorder::open_file() {
    if (writer_) return;
    io::recording::RecordingOptions o;
    o.t0_s = run_.t0_s;
    o.dt_s = run_.dt_s;
    o.chunk_bytes = chunk_bytes_;
    if (std::ifstream f(std::filesystem::path(run_.out_dir) / "run.yaml"); f) {
        std::ostringstream text;
        text << f.rdbuf();
        o.run_yaml = text.str();
    }
    o.run_metadata = io::recording::run_metadata(run_, o.run_yaml);
    if (viewer_) o.derived_channels = viewer_->channels();
    std::vector<std::string> topics;
    for (const auto& tr : tracks_) topics.push_back(tr->input->topic());
    writer_ = std::make_unique<io::recording::RecordingWriter>(dir_, topics, std::move(o));
}

void Recorder::step(const framework::StepContext& ctx) {
    if (dir_.empty()) return;
    open_file();
    if (viewer_) {
        viewer_out_.clear();
        viewer_->encode(ctx, ctx.k * io::recording::step_ns(run_.dt_s), viewer_out_);
        for (const auto& [channel, cdr] : viewer_out_) writer_->append_encoded(channel, ctx.k, cdr);
    }
    if (ctx.k % decimation_ != 0) return;
    for (std::size_t i = 0; i < tracks_.size(); ++i) {
        Track* tr = tracks_[i].get();
        if (!tr->input->available()) {
            if (tr->input->lost() && !tr->lost_reported) {
                tr->lost_reported = true;
                tr->lost_at = ctx.k;
            }
            continue;
        }
        writer_->append(i, ctx.k, tr->input->data_ptr());
    }
}

void Recorder::finish(bool completed) {
    if (finished_ || dir_.empty()) return;
    finished_ = true;
    open_file();  // a run that ended before its first step still gets an (empty) recording and a digest
    std::map<std::string, std::uint64_t> lost_at;
    for (auto& tr : tracks_)
        if (tr->lost_reported) lost_at[tr->input->topic()] = tr->lost_at;
    writer_->close(completed, lost_at);
    spdlog::debug("recorder: wrote {}", dir_);
}

void register_recorder(framework::ComponentRegistry& reg) {
    reg.add("recorder", "records topics to <out>/record (run.mcap: indexed MCAP, CDR + omgidl; digest.yaml)",
            framework::make_factory<Recorder>());
}

}  // namespace gdnav::recorder
