#include "framework/topic_types.hpp"

#include <map>
#include <stdexcept>

#include "framework/any_output.hpp"
#include "msgs/idl_text.hpp"
#include "msgs/messages.hpp"

namespace gdnav::framework {

namespace {
struct Entry {
    const msg::MessageOps* ops;
    std::string_view schema_idl;
};
std::map<std::string, Entry>& table() {
    static std::map<std::string, Entry> t;
    return t;
}
}  // namespace

void register_topic(const std::string& topic, const msg::MessageOps& ops, std::string_view schema_idl) {
    table()[topic] = Entry{&ops, schema_idl};
}

const msg::MessageOps* find_topic(const std::string& topic) {
    auto it = table().find(topic);
    return it == table().end() ? nullptr : it->second.ops;
}

const msg::MessageOps& require_topic(const std::string& topic) {
    if (const msg::MessageOps* ops = find_topic(topic)) return *ops;
    std::string known;
    for (const auto& t : known_topics()) known += (known.empty() ? "" : ", ") + t;
    throw std::invalid_argument("unknown topic '" + topic + "' (known: " + known + ")");
}

std::string_view topic_schema_idl(const std::string& topic) {
    auto it = table().find(topic);
    return it == table().end() ? std::string_view{} : it->second.schema_idl;
}

std::vector<std::string> known_topics() {
    std::vector<std::string> v;
    for (const auto& [k, _] : table()) v.push_back(k);
    return v;
}

void register_gdnav_topics() {
    register_topic<msg::Truth>(topics::kTruth, msg::idl_text::gdnav());
    register_topic<msg::ImuSample>(topics::kImu, msg::idl_text::gdnav());
    register_topic<msg::MagSample>(topics::kMag, msg::idl_text::gdnav());
    register_topic<msg::AirSample>(topics::kAir, msg::idl_text::gdnav());
    register_topic<msg::AtmSample>(topics::kAtm, msg::idl_text::gdnav());
    register_topic<msg::GnssSample>(topics::kGnss, msg::idl_text::gdnav());
    register_topic<msg::AirDataEstimate>(topics::kAirData, msg::idl_text::gdnav());
    register_topic<msg::AttitudeEstimate>(topics::kAttitude, msg::idl_text::gdnav());
    register_topic<msg::PositionEstimate>(topics::kPosition, msg::idl_text::gdnav());
    register_topic<msg::GuidanceTargets>(topics::kGuidance, msg::idl_text::gdnav());
    register_topic<msg::ControlCommands>(topics::kControls, msg::idl_text::gdnav());
}

}  // namespace gdnav::framework
