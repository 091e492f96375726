#include "io/foxglove_ws/protocol.hpp"

#include <nlohmann/json.hpp>

namespace gdnav::io::foxglove_ws {

using nlohmann::json;

std::string server_info_json(const std::string& name, const std::string& session_id) {
    return json{{"op", "serverInfo"}, {"name", name}, {"capabilities", json::array({"time"})}, {"sessionId", session_id}}
        .dump();
}

std::string advertise_json(const std::vector<Channel>& channels, std::uint32_t first_id) {
    json list = json::array();
    std::uint32_t id = first_id;
    for (const Channel& c : channels)
        list.push_back({{"id", id++},
                        {"topic", c.topic},
                        {"encoding", c.encoding},
                        {"schemaName", c.schema_name},
                        {"schemaEncoding", c.schema_encoding},
                        {"schema", c.schema}});
    return json{{"op", "advertise"}, {"channels", std::move(list)}}.dump();
}

std::string status_json(StatusLevel level, const std::string& message) {
    return json{{"op", "status"}, {"level", static_cast<int>(level)}, {"message", message}}.dump();
}

namespace {
void put_le(std::uint8_t* p, std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i) p[i] = static_cast<std::uint8_t>(v >> (8 * i));
}
}  // namespace

void message_data_header(std::uint8_t* out, std::uint32_t subscription_id, std::uint64_t log_time_ns) {
    out[0] = kOpMessageData;
    put_le(out + 1, subscription_id, 4);
    put_le(out + 5, log_time_ns, 8);
}

std::vector<std::uint8_t> time_message(std::uint64_t time_ns) {
    std::vector<std::uint8_t> m(9);
    m[0] = kOpTime;
    put_le(m.data() + 1, time_ns, 8);
    return m;
}

namespace {
std::uint32_t id_of(const json& j, const char* key) {
    const json& v = j.at(key);
    if (!v.is_number_unsigned() || v.get<std::uint64_t>() > UINT32_MAX)
        throw std::invalid_argument(std::string("'") + key + "' is not an unsigned 32-bit integer");
    return v.get<std::uint32_t>();
}
}  // namespace

ClientRequest parse_client_request(std::string_view text) {
    ClientRequest r;
    try {
        const json j = json::parse(text);
        if (!j.is_object() || !j.contains("op") || !j.at("op").is_string()) {
            r.problem = "not a JSON object with a string 'op'";
            return r;
        }
        r.op = j.at("op").get<std::string>();
        if (r.op == "subscribe") {
            for (const json& s : j.at("subscriptions")) r.subscriptions.emplace_back(id_of(s, "id"), id_of(s, "channelId"));
            r.kind = ClientRequest::Kind::Subscribe;
        } else if (r.op == "unsubscribe") {
            for (const json& s : j.at("subscriptionIds")) {
                if (!s.is_number_unsigned() || s.get<std::uint64_t>() > UINT32_MAX)
                    throw std::invalid_argument("'subscriptionIds' holds a value that is not an unsigned 32-bit integer");
                r.unsubscriptions.push_back(s.get<std::uint32_t>());
            }
            r.kind = ClientRequest::Kind::Unsubscribe;
        } else {
            r.kind = ClientRequest::Kind::Unsupported;
        }
    } catch (const std::exception& e) {
        r.kind = ClientRequest::Kind::Invalid;
        r.problem = e.what();
    }
    return r;
}

}  // namespace gdnav::io::foxglove_ws
