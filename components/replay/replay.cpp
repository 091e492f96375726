#include "replay.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include <spdlog/spdlog.h>

#include "framework/topic_types.hpp"

namespace gdnav::replay {

namespace fs = std::filesystem;
using io::recording::digest_hex;
using io::recording::DigestFile;
using io::recording::known_topics_list;
using io::recording::read_digest_file;
using io::recording::read_recording;
using io::recording::RecordEntry;
using io::recording::resolve_topic;

// An output of a type chosen at configure time: a buffer made by the topic's MessageOps.
class Replay::RecordedOutput final : public framework::OutputBase {
public:
    RecordedOutput(Component& owner, const std::string& topic, const msg::MessageOps& ops)
        : OutputBase(owner, topic, ops), value_(ops.create()) {}
    ~RecordedOutput() override { ops().destroy(value_); }
    [[nodiscard]] void* data() override { return value_; }

private:
    void* value_;
};

Replay::Replay(std::string name) : Component(std::move(name)) {}
Replay::~Replay() = default;

namespace {

// True when the sample of `e` carries exactly the stamp time this run gives its step (t0_s + k dt_s): the stamp is
// rewritten with the run's time and the encodings compared, so no per-type accessor is needed.
bool stamped_on_run_grid(const TopicRecord& r, const RecordEntry& e, const framework::RunInfo& run, SampleDecoder& dec,
                         void* scratch, void* restamped) {
    if (!dec.decode(&r.bytes[e.offset], e.size, scratch)) return false;
    if (r.ops->step_of(scratch) == UINT64_MAX) return true;  // unstamped type: nothing to compare
    r.ops->copy(restamped, scratch);
    r.ops->set_stamp(restamped, r.ops->run_of(scratch), e.step, run.time_of(e.step));
    std::vector<std::uint8_t> a, b;
    r.ops->serialize(scratch, a);
    r.ops->serialize(restamped, b);
    return a == b;
}

}  // namespace

void Replay::configure(const config::Config& cfg, const framework::RunInfo& run, rnd::Stream&) {
    const fs::path dir = cfg.get_string("record");
    const auto names = cfg.get_strings("topics");
    if (names.empty()) cfg.fail("topics", "at least one topic is required");
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) cfg.fail("record", "'" + dir.string() + "' is not a directory");
    DigestFile digest;
    try {
        digest = read_digest_file(dir);
    } catch (const std::runtime_error& e) {
        cfg.fail("record", e.what());
    }
    if (digest.present && !digest.complete)
        spdlog::debug("replay: {}/digest.yaml says the recording did not end normally", dir.string());
    std::set<std::string> seen;
    std::vector<std::string> topics;
    for (const auto& name : names) {
        const std::string topic = resolve_topic(name);
        if (topic.empty()) cfg.fail("topics", "unknown topic '" + name + "' (known: " + known_topics_list() + ")");
        if (!seen.insert(topic).second) cfg.fail("topics", "topic '" + topic + "' is listed twice");
        topics.push_back(topic);
    }
    io::recording::Recording recording;
    try {
        recording = read_recording(dir, topics);
    } catch (const std::runtime_error& e) {
        cfg.fail("record", e.what());
    }
    for (const auto& topic : topics) {
        auto tr = std::make_unique<Track>();
        tr->record = std::move(recording.topics.at(topic));
        const TopicRecord& r = tr->record;
        const std::string file = r.file.string() + ": " + r.topic;
        if (auto it = digest.digests.find(topic); it != digest.digests.end() && it->second != digest_hex(r.digest))
            cfg.fail("record", file + ": content (digest " + digest_hex(r.digest) + ") differs from digest.yaml (" +
                                   it->second + "): the file was changed or truncated");
        if (r.entries.empty()) cfg.fail("record", file + ": no samples");
        if (r.entries.front().step != 0)
            cfg.fail("record", file + ": first sample at step " + std::to_string(r.entries.front().step) +
                                   "; a replay needs a sample at step 0");
        const std::uint64_t last_needed = run.steps > 0 ? run.steps - 1 : 0;
        if (r.entries.back().step < last_needed)
            cfg.fail("record", file + ": last sample at step " + std::to_string(r.entries.back().step) +
                                   " but the run needs steps 0.." + std::to_string(last_needed) +
                                   " (shorten the run with --steps " + std::to_string(r.entries.back().step + 1) + ")");
        tr->decoder = std::make_unique<SampleDecoder>(*r.ops);
        {
            std::unique_ptr<void, void (*)(void*)> a(r.ops->create(), r.ops->destroy);
            std::unique_ptr<void, void (*)(void*)> b(r.ops->create(), r.ops->destroy);
            for (const RecordEntry* e : {&r.entries.front(), &r.entries.back()})
                if (!stamped_on_run_grid(r, *e, run, *tr->decoder, a.get(), b.get()))
                    cfg.fail("record", file + ": the sample of step " + std::to_string(e->step) +
                                           " is not stamped t = t0_s + k*dt_s of this run (t0_s = " +
                                           std::to_string(run.t0_s) + ", dt_s = " + std::to_string(run.dt_s) +
                                           "): recorded or imported on another time grid");
        }
        // Held steps (no record) within the run, and the largest gap between consecutive records.
        std::uint64_t recorded = 0, prev = 0;
        for (const RecordEntry& e : r.entries) {
            if (e.step >= run.steps) break;
            ++recorded;
            tr->largest_gap = std::max(tr->largest_gap, e.step - prev);
            prev = e.step;
        }
        tr->held_steps = run.steps - recorded;
        tr->output = std::make_unique<RecordedOutput>(*this, topic, *r.ops);
        tracks_.push_back(std::move(tr));
    }
    cfg.finish();
}

void Replay::step(const framework::StepContext& ctx) {
    if (!reported_) {
        reported_ = true;
        for (const auto& tr : tracks_)
            if (tr->held_steps > 0)
                spdlog::warn("replay: {}: {} steps have no record and repeat the previous sample (largest gap {} steps)",
                             tr->record.file.string(), tr->held_steps, tr->largest_gap);
    }
    for (const auto& tr : tracks_) {
        const auto& entries = tr->record.entries;
        const std::size_t before = tr->next;
        while (tr->next < entries.size() && entries[tr->next].step <= ctx.k) ++tr->next;
        if (tr->next == before) continue;  // no newer record: hold the last sample
        const RecordEntry& e = entries[tr->next - 1];
        if (!tr->decoder->decode(&tr->record.bytes[e.offset], e.size, tr->output->data()))
            throw std::runtime_error("replay: " + tr->record.file.string() + ": cannot decode the sample of step " +
                                     std::to_string(e.step));
    }
}

void register_replay(framework::ComponentRegistry& reg) {
    reg.add("replay", "publishes recorded topics (<record>/run.mcap) at their recorded steps (docs/replay.md)",
            framework::make_factory<Replay>());
}

}  // namespace gdnav::replay
