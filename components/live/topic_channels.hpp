#pragma once
// The raw gdnav topics as live channels, exactly as the recording's channels (common/io/recording/record_file.hpp):
// topic = the gdnav topic name, message encoding `cdr`, schema encoding `omgidl`, schema name = the fully-qualified
// IDL type, schema = the text of idl/gdnav.idl (runtime::topic_schema_idl); each message = the sample's CDR
// encoding with its encapsulation header (runtime::MessageOps::serialize, as the recorder writes it).
#include <memory>
#include <string>
#include <vector>

#include "channel_source.hpp"

namespace gdnav::live {

class TopicChannels final : public ChannelSource {
public:
    // Declares a Lag::Same input of `owner` per topic (full names of known topics); streams every `decimation`-th
    // step (k % decimation == 0).
    TopicChannels(runtime::Component& owner, const std::vector<std::string>& topics, std::uint64_t decimation);
    [[nodiscard]] std::vector<foxglove_ws::Channel> channels() const override;
    void encode(const runtime::StepContext& ctx, std::uint64_t log_time_ns, std::uint32_t first_id,
                const foxglove_ws::Server& server, foxglove_ws::Frame& frame) override;

private:
    std::vector<std::unique_ptr<runtime::InputBase>> inputs_;
    std::vector<std::uint8_t> buffer_;
    std::uint64_t decimation_;
};

}  // namespace gdnav::live
