#include "viewer_source.hpp"

namespace gdnav::live {

ViewerSource::ViewerSource(framework::Component& owner, std::uint64_t decimation)
    : channels_(owner, io::viewer::ViewerOptions{decimation}) {}

std::vector<io::foxglove_ws::Channel> ViewerSource::channels() const {
    std::vector<io::foxglove_ws::Channel> v;
    for (const auto& c : channels_.channels())
        v.push_back({c.topic, c.message_encoding, c.schema_name, c.schema_encoding, c.schema});
    return v;
}

void ViewerSource::encode(const framework::StepContext& ctx, std::uint64_t log_time_ns, std::uint32_t first_id,
                          const io::foxglove_ws::Server& server, io::foxglove_ws::Frame& frame) {
    if (channels_.has_origin() && !server.any_subscribed()) return;  // until then encode() looks for its origin
    out_.clear();
    channels_.encode(ctx, log_time_ns, out_);
    for (const auto& [index, cdr] : out_) {
        const auto id = static_cast<std::uint32_t>(first_id + index);
        if (server.subscribed(id)) frame.add(id, cdr.data(), cdr.size());
    }
}

}  // namespace gdnav::live
