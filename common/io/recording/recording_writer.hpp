#pragma once
// Writes a recording (record_file.hpp: <dir>/run.mcap and <dir>/digest.yaml) — the recorder and `gdnav import-log`.
//
// append() only serialises the sample into a batch; a writer thread digests the batches, writes the MCAP messages
// and compresses the chunks (zstd), so that recording costs the simulation little more than the serialisation
// (at most kMaxQueued batches wait; append() blocks beyond). close() drains the thread; errors of the writer thread
// are thrown by the next append() or close().
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "io/mcap/mcap_writer.hpp"
#include "io/recording/record_file.hpp"
#include "io/viewer/viewer_channels.hpp"

namespace gdnav::io::recording {

struct RecordingOptions {
    double t0_s{0.0};  // simulated time of step 0 (the log-time epoch)
    double dt_s{0.01};
    std::map<std::string, std::string> run_metadata;  // the "gdnav.run" metadata record (run_metadata.hpp)
    std::string run_yaml;                             // attached as run.yaml when not empty
    std::size_t chunk_bytes{1u << 20};                // uncompressed bytes per MCAP chunk
    std::vector<viewer::ViewerChannel> derived_channels;  // channels of already-encoded messages, after the topics
};

class RecordingWriter {
public:
    // Opens <dir>/run.mcap (truncates) and writes the header, one schema and channel per topic (full names, known
    // topics) and per derived channel (options.derived_channels), the metadata and the run.yaml attachment.
    RecordingWriter(const std::filesystem::path& dir, const std::vector<std::string>& topics, RecordingOptions options);
    ~RecordingWriter();
    RecordingWriter(const RecordingWriter&) = delete;
    RecordingWriter& operator=(const RecordingWriter&) = delete;

    // Serialises `sample` (an object of topic i's type) as the message of `step` (steps strictly increase per topic).
    void append(std::size_t topic_index, std::uint64_t step, const void* sample);
    // Appends the already-encoded message `cdr` of derived channel i as the message of `step` (steps strictly
    // increase per channel). Derived channels are digested and counted like topics (digest.yaml, gdnav.end).
    void append_encoded(std::size_t derived_index, std::uint64_t step, const std::vector<std::uint8_t>& cdr);
    // Writes metadata "gdnav.end" (complete, per-topic samples, lost_at_step), closes the MCAP file (summary,
    // index, footer) and writes digest.yaml. `lost_at`: topics whose producer died -> first step without a sample.
    void close(bool complete, const std::map<std::string, std::uint64_t>& lost_at = {});

private:
    static constexpr std::size_t kBatchBytes = 256 * 1024;
    static constexpr std::size_t kMaxQueued = 8;
    struct Track {
        std::string topic;
        const msg::MessageOps* ops;  // nullptr: a derived channel
        std::uint16_t channel;
        std::uint64_t appended{0}, last_appended{0};     // the caller's side
        std::uint64_t samples{0}, last_step{0}, digest{kFnvBasis};  // the writer thread's side
    };
    struct Item {
        std::uint32_t track;
        std::uint32_t size;
        std::uint64_t step;
    };
    struct Batch {
        std::vector<std::uint8_t> bytes;  // the CDR payloads of `items`, one after the other
        std::vector<Item> items;
    };
    void add_item(std::size_t track, std::uint64_t step, const std::vector<std::uint8_t>& cdr);
    void submit();
    void write_batches();  // the writer thread
    void stop_thread();
    void rethrow();

    std::filesystem::path dir_;
    std::uint64_t step_ns_;
    std::unique_ptr<mcap::Writer> mcap_;
    std::vector<Track> tracks_;  // the topics, then the derived channels
    std::size_t topic_count_{0};
    std::vector<std::uint8_t> buffer_;
    Batch batch_;
    std::mutex mutex_;
    std::condition_variable queued_, space_;
    std::deque<Batch> queue_;
    bool stopping_{false};
    std::exception_ptr error_;
    std::thread thread_;
    bool closed_{false};
};

}  // namespace gdnav::io::recording
