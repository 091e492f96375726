#include "io/recording/recording_writer.hpp"

#include <fstream>
#include <stdexcept>

#include "framework/topic_types.hpp"

namespace gdnav::io::recording {

namespace fs = std::filesystem;

RecordingWriter::RecordingWriter(const fs::path& dir, const std::vector<std::string>& topics, RecordingOptions o)
    : dir_(dir), step_ns_(step_ns(o.dt_s)) {
    fs::create_directories(dir);
    std::error_code ec;
    fs::remove(dir / "digest.yaml", ec);  // a digest of an earlier recording would not match this one
    mcap::WriterOptions mo;
    mo.profile = kProfile;
    mo.library = std::string("gdnav ") + GDNAV_VERSION;
    mo.chunk_bytes = o.chunk_bytes;
    mcap_ = std::make_unique<mcap::Writer>(recording_file(dir), mo);
    mcap_->write_metadata(kRunMetadataName, o.run_metadata);
    if (!o.run_yaml.empty()) mcap_->write_attachment(kRunYamlAttachment, "application/yaml", 0, 0, o.run_yaml);
    std::map<std::string, std::uint16_t> schema_ids;  // type name -> schema
    for (const auto& topic : topics) {
        const msg::MessageOps* ops = framework::find_topic(topic);
        if (!ops) throw std::runtime_error("unknown topic '" + topic + "' (known: " + known_topics_list() + ")");
        auto it = schema_ids.find(ops->type_name);
        if (it == schema_ids.end()) {
            const std::string_view idl = framework::topic_schema_idl(topic);
            it = schema_ids.emplace(ops->type_name, mcap_->add_schema(ops->type_name, kSchemaEncoding, std::string(idl)))
                     .first;
        }
        const std::uint16_t channel = mcap_->add_channel(it->second, topic, kMessageEncoding);
        tracks_.push_back(Track{topic, ops, channel});
    }
    for (const auto& d : o.derived_channels) {
        auto it = schema_ids.find(d.schema_name);
        if (it == schema_ids.end())
            it = schema_ids.emplace(d.schema_name, mcap_->add_schema(d.schema_name, d.schema_encoding, d.schema)).first;
        tracks_.push_back(Track{d.topic, nullptr, mcap_->add_channel(it->second, d.topic, d.message_encoding)});
    }
    topic_count_ = topics.size();
    batch_.bytes.reserve(kBatchBytes + 4096);
    thread_ = std::thread([this] { write_batches(); });
}

RecordingWriter::~RecordingWriter() { stop_thread(); }  // unclosed: the MCAP writer completes the file

void RecordingWriter::append(std::size_t i, std::uint64_t step, const void* sample) {
    if (i >= topic_count_) throw std::logic_error("RecordingWriter: no topic " + std::to_string(i));
    tracks_[i].ops->serialize(sample, buffer_);
    add_item(i, step, buffer_);
}

void RecordingWriter::append_encoded(std::size_t derived_index, std::uint64_t step, const std::vector<std::uint8_t>& cdr) {
    const std::size_t i = topic_count_ + derived_index;
    if (i >= tracks_.size()) throw std::logic_error("RecordingWriter: no derived channel " + std::to_string(derived_index));
    add_item(i, step, cdr);
}

void RecordingWriter::add_item(std::size_t i, std::uint64_t step, const std::vector<std::uint8_t>& cdr) {
    Track& t = tracks_[i];
    if (t.appended > 0 && step <= t.last_appended)
        throw std::logic_error("RecordingWriter: steps must increase (" + t.topic + ")");
    batch_.items.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(cdr.size()), step});
    batch_.bytes.insert(batch_.bytes.end(), cdr.begin(), cdr.end());
    ++t.appended;
    t.last_appended = step;
    if (batch_.bytes.size() >= kBatchBytes) submit();
}

void RecordingWriter::submit() {
    std::unique_lock lock(mutex_);
    space_.wait(lock, [this] { return queue_.size() < kMaxQueued || error_; });
    if (error_) {
        lock.unlock();
        rethrow();
    }
    queue_.push_back(std::move(batch_));
    batch_ = Batch{};
    batch_.bytes.reserve(kBatchBytes + 4096);
    queued_.notify_one();
}

void RecordingWriter::write_batches() {
    while (true) {
        Batch b;
        {
            std::unique_lock lock(mutex_);
            queued_.wait(lock, [this] { return !queue_.empty() || stopping_; });
            if (queue_.empty()) return;  // stopping, all written
            b = std::move(queue_.front());
            queue_.pop_front();
            space_.notify_one();
        }
        try {
            std::size_t at = 0;
            for (const Item& it : b.items) {
                Track& t = tracks_[it.track];
                const std::uint8_t* data = b.bytes.data() + at;
                const std::uint64_t log_time = it.step * step_ns_;
                mcap_->write_message(t.channel, static_cast<std::uint32_t>(it.step), log_time, log_time, data, it.size);
                t.digest = digest_sample(t.digest, it.step, data, it.size);
                ++t.samples;
                t.last_step = it.step;
                at += it.size;
            }
        } catch (...) {
            std::lock_guard lock(mutex_);
            error_ = std::current_exception();
            queue_.clear();
            space_.notify_all();
            return;
        }
    }
}

void RecordingWriter::stop_thread() {
    if (!thread_.joinable()) return;
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    queued_.notify_one();
    thread_.join();
}

void RecordingWriter::rethrow() {
    std::exception_ptr e;
    {
        std::lock_guard lock(mutex_);
        e = error_;
    }
    if (e) std::rethrow_exception(e);
}

void RecordingWriter::close(bool complete, const std::map<std::string, std::uint64_t>& lost_at) {
    if (closed_) return;
    closed_ = true;
    if (!batch_.items.empty()) submit();
    stop_thread();
    rethrow();
    mcap::StringMap end{{"complete", complete ? "true" : "false"}};
    for (const Track& t : tracks_) {
        end[t.topic + ".samples"] = std::to_string(t.samples);
        end[t.topic + ".digest"] = digest_hex(t.digest);
        if (auto it = lost_at.find(t.topic); it != lost_at.end()) end[t.topic + ".lost_at_step"] = std::to_string(it->second);
    }
    mcap_->write_metadata(kEndMetadataName, end);
    mcap_->close();
    const fs::path f = dir_ / "digest.yaml";
    std::ofstream d(f);
    d << "complete: " << (complete ? "true" : "false") << "\ntopics:\n";
    for (const Track& t : tracks_) {
        d << "  " << t.topic << ": {samples: " << t.samples << ", last_step: " << t.last_step << ", digest: \""
          << digest_hex(t.digest) << "\"";
        if (auto it = lost_at.find(t.topic); it != lost_at.end()) d << ", lost_at_step: " << it->second;
        d << "}\n";
    }
    if (!d) throw std::runtime_error(f.string() + ": write error");
}

}  // namespace gdnav::io::recording
