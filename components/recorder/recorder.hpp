#pragma once
// recorder: subscribes to a configured list of topics and writes every sample in lockstep order.
//
//   recorder: {type: recorder, topics: [gdnav/ImuSample, ...], decimation: 1, chunk_kib: 1024,
//              viewer: false, viewer_decimation: 10}
//
// viewer: true adds the viewer channels (common/io/viewer/viewer_channels.hpp: Foxglove LocationFix and
// FrameTransform of the true and estimated state, the navigation errors) every `viewer_decimation` steps; the run
// then needs producers of Truth and the three estimates. `topics` may be empty when viewer is true.
//
// Files in <out_dir>/record/ (record_file.hpp):
//   run.mcap      — one indexed MCAP file, a channel per topic (CDR messages, omgidl schemas), one message per
//                   recorded step, zstd chunks of `chunk_kib` KiB of records written as they fill (a killed run keeps
//                   every chunk written before), run metadata and the run.yaml attachment; summary and index at the
//                   end of a normal run.
//   digest.yaml   — per topic: samples, last_step, FNV-1a 64 digest of all its samples; `complete: true` only when
//                   the run finished normally. Two runs are bit-identical iff their digests are equal.
// Inputs whose producer dies are recorded up to the last step they delivered (`lost_at_step` in the digest).
#include <cstdint>
#include <memory>
#include <vector>

#include "io/recording/recording_writer.hpp"
#include "framework/component.hpp"
#include "framework/registry.hpp"
#include "io/viewer/viewer_channels.hpp"

namespace gdnav::recorder {

class Recorder final : public framework::Component {
public:
    explicit Recorder(std::string name) : Component(std::move(name)) {}
    void configure(const config::Config& cfg, const framework::RunInfo& run, rnd::Stream& stream) override;
    void step(const framework::StepContext& ctx) override;
    void finish(bool completed) override;

private:
    struct Track {
        std::unique_ptr<framework::InputBase> input;
        bool lost_reported{false};
        std::uint64_t lost_at{0};
    };
    void open_file();
    std::vector<std::unique_ptr<Track>> tracks_;
    std::unique_ptr<io::viewer::ViewerChannels> viewer_;  // the viewer channels (viewer: true), after the topics
    std::vector<io::viewer::ViewerMessage> viewer_out_;
    std::unique_ptr<io::recording::RecordingWriter> writer_;  // opened at the first step (run.yaml is written by then)
    framework::RunInfo run_;
    std::string dir_;
    std::uint64_t decimation_{1};
    std::size_t chunk_bytes_{1u << 20};
    bool finished_{false};
};

void register_recorder(framework::ComponentRegistry& reg);

}  // namespace gdnav::recorder
