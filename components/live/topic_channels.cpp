#include "topic_channels.hpp"

#include <stdexcept>

#include "io/recording/record_file.hpp"
#include "framework/topic_types.hpp"

namespace gdnav::live {

TopicChannels::TopicChannels(runtime::Component& owner, const std::vector<std::string>& topics, std::uint64_t decimation)
    : decimation_(decimation) {
    for (const auto& t : topics) {
        const runtime::MessageOps* ops = runtime::find_topic(t);
        if (!ops) throw std::invalid_argument("unknown topic '" + t + "'");
        inputs_.push_back(std::make_unique<runtime::InputBase>(owner, t, runtime::Lag::Same, *ops));
    }
}

std::vector<foxglove_ws::Channel> TopicChannels::channels() const {
    std::vector<foxglove_ws::Channel> out;
    for (const auto& in : inputs_)
        out.push_back({in->topic(), recorder::kMessageEncoding, in->ops().type_name, recorder::kSchemaEncoding,
                       std::string(runtime::topic_schema_idl(in->topic()))});
    return out;
}

void TopicChannels::encode(const runtime::StepContext& ctx, std::uint64_t, std::uint32_t first_id,
                           const foxglove_ws::Server& server, foxglove_ws::Frame& frame) {
    if (ctx.k % decimation_ != 0 || !server.any_subscribed()) return;
    for (std::size_t i = 0; i < inputs_.size(); ++i) {
        const auto id = static_cast<std::uint32_t>(first_id + i);
        const runtime::InputBase& in = *inputs_[i];
        if (!in.available() || !server.subscribed(id)) continue;
        in.ops().serialize(in.data_ptr(), buffer_);
        frame.add(id, buffer_.data(), buffer_.size());
    }
}

}  // namespace gdnav::live
