#pragma once
// The raw gdnav topics as live channels, exactly as the recording's channels (common/io/recording/record_file.hpp):
// topic = the gdnav topic name, message encoding `cdr`, schema encoding `omgidl`, schema name = the fully-qualified
// IDL type, schema = the text of idl/gdnav.idl (framework::topic_schema_idl); each message = the sample's CDR
// encoding with its encapsulation header (msg::MessageOps::serialize, as the recorder writes it).
#include <memory>
#include <string>
#include <vector>

#include "channel_source.hpp"

namespace gdnav::live {

class TopicChannels final : public ChannelSource {
public:
    // Declares a Lag::Same input of `owner` per topic (full names of known topics); streams every `decimation`-th
    // step (k % decimation == 0).
    TopicChannels(framework::Component& owner, const std::vector<std::string>& topics, std::uint64_t decimation);
    [[nodiscard]] std::vector<io::foxglove_ws::Channel> channels() const override;
    void encode(const framework::StepContext& ctx, std::uint64_t log_time_ns, std::uint32_t first_id,
                const io::foxglove_ws::Server& server, io::foxglove_ws::Frame& frame) override;

private:
    std::vector<std::unique_ptr<framework::InputBase>> inputs_;
    std::vector<std::uint8_t> buffer_;
    std::uint64_t decimation_;
};

}  // namespace gdnav::live
