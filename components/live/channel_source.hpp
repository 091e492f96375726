#pragma once
// What the live bridge streams: sources of channels, each giving its channels once (advertised) and, every streamed
// step, the messages of the channels some client subscribed to. The raw gdnav topics are one source
// (topic_channels.hpp), the derived viewer channels another (viewer_source.hpp); see live_bridge.hpp, "Adding
// channels".
#include <cstdint>
#include <vector>

#include "io/foxglove_ws/server.hpp"
#include "framework/component.hpp"

namespace gdnav::live {

class ChannelSource {
public:
    virtual ~ChannelSource() = default;
    // The source's channels, in a fixed order; the bridge gives them the ids first_id, first_id + 1, ...
    [[nodiscard]] virtual std::vector<io::foxglove_ws::Channel> channels() const = 0;
    // Called at every step: adds to `frame` the message of step ctx.k (log time `log_time_ns`) of each channel i
    // whose id (first_id + i) `server` reports as subscribed, at the steps the source streams (its own decimation),
    // and only those: the rest should cost (next to) nothing. Runs in the member's step: no blocking, no I/O.
    virtual void encode(const framework::StepContext& ctx, std::uint64_t log_time_ns, std::uint32_t first_id,
                        const io::foxglove_ws::Server& server, io::foxglove_ws::Frame& frame) = 0;
};

}  // namespace gdnav::live
