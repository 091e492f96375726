#include "runtime/topic_types.hpp"

#include <map>

#include "runtime/messages.hpp"

namespace gdnav::runtime {

namespace {
std::map<std::string, const MessageOps*>& table() {
    static std::map<std::string, const MessageOps*> t;
    return t;
}
}  // namespace

void register_topic(const std::string& topic, const MessageOps& ops) { table()[topic] = &ops; }

const MessageOps* find_topic(const std::string& topic) {
    auto it = table().find(topic);
    return it == table().end() ? nullptr : it->second;
}

std::vector<std::string> known_topics() {
    std::vector<std::string> v;
    for (const auto& [k, _] : table()) v.push_back(k);
    return v;
}

void register_gdnav_topics() {
    register_topic<msg::Truth>(topics::kTruth);
    register_topic<msg::ImuSample>(topics::kImu);
    register_topic<msg::MagSample>(topics::kMag);
    register_topic<msg::AirSample>(topics::kAir);
    register_topic<msg::AtmSample>(topics::kAtm);
    register_topic<msg::GnssSample>(topics::kGnss);
    register_topic<msg::AirDataEstimate>(topics::kAirData);
    register_topic<msg::AttitudeEstimate>(topics::kAttitude);
    register_topic<msg::PositionEstimate>(topics::kPosition);
    register_topic<msg::GuidanceTargets>(topics::kGuidance);
    register_topic<msg::ControlCommands>(topics::kControls);
}

}  // namespace gdnav::runtime
