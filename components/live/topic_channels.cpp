#include "topic_channels.hpp"

#include <stdexcept>

#include "io/recording/record_file.hpp"
#include "framework/topic_types.hpp"

namespace gdnav::live {

TopicChannels::TopicChannels(framework::Component& owner, const std::vector<std::string>& topics,
                             std::uint64_t decimation)
    : decimation_(decimation) {
    for (const auto& t : topics) {
        const msg::MessageOps* ops = framework::find_topic(t);
        if (!ops) throw std::invalid_argument("unknown topic '" + t + "'");
        inputs_.push_back(std::make_unique<framework::InputBase>(owner, t, framework::Lag::Same, *ops));
    }
}

std::vector<io::foxglove_ws::Channel> TopicChannels::channels() const {
    std::vector<io::foxglove_ws::Channel> out;
    for (const auto& in : inputs_)
        out.push_back({in->topic(), io::recording::kMessageEncoding, in->ops().type_name,
                       io::recording::kSchemaEncoding, std::string(framework::topic_schema_idl(in->topic()))});
    return out;
}

void TopicChannels::encode(const framework::StepContext& ctx, std::uint64_t, std::uint32_t first_id,
                           const io::foxglove_ws::Server& server, io::foxglove_ws::Frame& frame) {
    if (ctx.k % decimation_ != 0 || !server.any_subscribed()) return;
    for (std::size_t i = 0; i < inputs_.size(); ++i) {
        const auto id = static_cast<std::uint32_t>(first_id + i);
        const framework::InputBase& in = *inputs_[i];
        if (!in.available() || !server.subscribed(id)) continue;
        in.ops().serialize(in.data_ptr(), buffer_);
        frame.add(id, buffer_.data(), buffer_.size());
    }
}

}  // namespace gdnav::live
