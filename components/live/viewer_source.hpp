#pragma once
// The viewer channels (common/io/viewer: foxglove LocationFix / FrameTransform of the true and estimated state,
// gdnav NavErrors) as live channels, the same channels as a recording made with `--record ...,viewer`.
// ViewerChannels::encode() runs from the first step until it has seen a true position (its ENU origin, as in the
// recording), then only while some client is subscribed (it computes messages every `decimation` steps); the
// messages of the subscribed channels go into the frame.
#include <memory>
#include <vector>

#include "channel_source.hpp"
#include "io/viewer/viewer_channels.hpp"

namespace gdnav::live {

class ViewerSource final : public ChannelSource {
public:
    // Declares the viewer's inputs on `owner` where it has none (call after the owner's own inputs).
    ViewerSource(framework::Component& owner, std::uint64_t decimation);
    [[nodiscard]] std::vector<io::foxglove_ws::Channel> channels() const override;
    void encode(const framework::StepContext& ctx, std::uint64_t log_time_ns, std::uint32_t first_id,
                const io::foxglove_ws::Server& server, io::foxglove_ws::Frame& frame) override;

private:
    io::viewer::ViewerChannels channels_;
    std::vector<io::viewer::ViewerMessage> out_;
};

}  // namespace gdnav::live
