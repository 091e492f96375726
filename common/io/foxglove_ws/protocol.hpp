#pragma once
// The messages of the Foxglove WebSocket protocol v1 (subprotocol `foxglove.websocket.v1`,
// https://github.com/foxglove/ws-protocol/blob/main/docs/spec.md) that a data-streaming server needs:
//   server -> client  serverInfo, advertise, status (JSON text); Message Data (0x01) and Time (0x02) (binary)
//   client -> server  subscribe, unsubscribe (JSON text); anything else is answered with a status error
// Binary integers are little-endian. No sockets here (server.hpp, ws_endpoint.hpp).
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gdnav::io::foxglove_ws {

inline constexpr const char* kSubprotocol = "foxglove.websocket.v1";
inline constexpr std::uint8_t kOpMessageData = 0x01;
inline constexpr std::uint8_t kOpTime = 0x02;
inline constexpr std::size_t kMessageDataHeader = 1 + 4 + 8;  // opcode, subscription id, log time

// A channel as advertised: ids are given by the server (1, 2, ... in the order of the list).
struct Channel {
    std::string topic;
    std::string encoding;         // message encoding, e.g. "cdr"
    std::string schema_name;      // e.g. "gdnav::msg::ImuSample"
    std::string schema_encoding;  // e.g. "omgidl"
    std::string schema;           // the schema text
};

std::string server_info_json(const std::string& name, const std::string& session_id);
// `first_id`: the id of channels[0]; the others follow.
std::string advertise_json(const std::vector<Channel>& channels, std::uint32_t first_id);
enum class StatusLevel : int { Info = 0, Warning = 1, Error = 2 };
std::string status_json(StatusLevel level, const std::string& message);

// Message Data header (opcode 0x01, subscription id, log time ns); the payload follows it.
void message_data_header(std::uint8_t* out, std::uint32_t subscription_id, std::uint64_t log_time_ns);
// Time (opcode 0x02, timestamp ns).
std::vector<std::uint8_t> time_message(std::uint64_t time_ns);

// A client's text message, parsed.
struct ClientRequest {
    enum class Kind { Subscribe, Unsubscribe, Unsupported, Invalid } kind{Kind::Invalid};
    std::vector<std::pair<std::uint32_t, std::uint32_t>> subscriptions;  // Subscribe: (subscription id, channel id)
    std::vector<std::uint32_t> unsubscriptions;                          // Unsubscribe: subscription ids
    std::string op;       // the op as given (Unsupported)
    std::string problem;  // Invalid: why
};
ClientRequest parse_client_request(std::string_view text);

}  // namespace gdnav::io::foxglove_ws
