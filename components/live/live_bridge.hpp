#pragma once
// live: streams a run to Foxglove / Lichtblick over the Foxglove WebSocket protocol (common/io/foxglove_ws;
// docs/viewing.md "Live view"). Added by `gdnav run --live [PORT]` (common/launch/run_rewrites.cpp) or declared in a
// scenario:
//
//   live: {type: live, topics: [gdnav/Truth, ...], viewer: true, viewer_decimation: 10, port: 8765,
//          bind: 127.0.0.1, decimation: 10, max_pending_kib: 1024, queue_steps: 64}
//
//   topics           topics streamed (default: every data topic), one channel each, as in the recording
//   viewer           also the viewer channels (common/io/viewer; default false), every viewer_decimation steps
//   port, bind       where the WebSocket server listens (bind: an IPv4/IPv6 address or localhost; default loopback
//                    only); checked when the member is configured (a port in use is a configuration error)
//   decimation       stream the topics every N-th step (k % N == 0; default 10, 10 Hz at dt = 0.01 s)
//   max_pending_kib  per client: bytes not yet taken by its socket beyond which a frame is dropped for it
//   queue_steps      frames waiting for the server thread beyond which a frame is dropped for everybody
//
// An observer member (framework::Component::observer) that never makes the run wait: the server starts at the first
// step; a streamed step serialises the subscribed channels into one frame and hands it to the server thread
// (io::foxglove_ws::Server: bounded queue, per-client drop policy); with no subscribed client, or only stalled ones
// (io::foxglove_ws::Server: they are counted as dropping the steps skipped meanwhile), the topics cost nothing (the
// viewer channels, when on, are still computed every viewer_decimation steps, so that their ENU origin is the
// recording's). Log time = k * dt_ns, as in the recording. At the end the per-client sent/dropped counts are logged and
// written to <out>/<name>_stats.yaml. Its inputs have a stride (InputBase::set_stride of the topics' decimation, the
// viewer's, or both's greatest common divisor for an input both use; the stride is a divisor of that, from 4 to 10, or
// 1), so over DDS the producers send it one sample per stride, which includes every step it streams (at stride 10
// through their decimated mirrors of the topics, dds/host/mirror.hpp, where they write them).
//
// Adding channels: implement a ChannelSource (channel_source.hpp: channels() and encode(), as TopicChannels and
// ViewerSource do) and append it to `sources_` in configure(); the bridge gives it the next channel ids, advertises
// its channels and calls it at every step.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "channel_source.hpp"
#include "io/foxglove_ws/server.hpp"
#include "framework/registry.hpp"

namespace gdnav::live {

class LiveBridge final : public framework::Component {
public:
    explicit LiveBridge(std::string name) : Component(std::move(name)) {}
    ~LiveBridge() override;
    void configure(const config::Config& cfg, const framework::RunInfo& run, rnd::Stream& stream) override;
    void step(const framework::StepContext& ctx) override;
    void finish(bool completed) override;
    // Never holds the run: over DDS it is out of the barrier and reads with best-effort readers (a sample lost on
    // the way is a step not streamed, counted by the host; docs/viewing.md "Cost").
    [[nodiscard]] bool observer() const override { return true; }

private:
    void start_server();
    std::vector<std::unique_ptr<ChannelSource>> sources_;
    std::vector<std::uint32_t> first_ids_;  // per source
    io::foxglove_ws::ServerOptions options_;
    std::unique_ptr<io::foxglove_ws::Server> server_;
    framework::RunInfo run_;
    std::uint64_t decimation_{10};
    std::uint64_t step_ns_{0};
    std::uint64_t steps_streamed_{0};  // steps with a frame handed to the server
    std::uint64_t steps_skipped_{0};   // streamed steps not serialised: every subscribed client was stalled
    bool finished_{false};
};

void register_live(framework::ComponentRegistry& reg);

}  // namespace gdnav::live
