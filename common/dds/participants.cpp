#include "dds/participants.hpp"

#include <algorithm>

namespace gdnav::dds {

namespace {
constexpr const char* kPrefix = "gdnav-members=";
}

std::vector<unsigned char> announcement(const MemberNames& members) {
    if (members.empty()) return {};
    std::string s = kPrefix;
    for (std::size_t i = 0; i < members.size(); ++i) s += (i ? "," : "") + members[i];
    return {s.begin(), s.end()};
}

std::optional<MemberNames> announced_members(const std::vector<unsigned char>& user_data) {
    const std::string s(user_data.begin(), user_data.end());
    const std::string prefix = kPrefix;
    if (s.compare(0, prefix.size(), prefix) != 0 || s.size() == prefix.size()) return std::nullopt;
    MemberNames names;
    std::size_t b = prefix.size();
    while (b <= s.size()) {
        std::size_t e = s.find(',', b);
        if (e == std::string::npos) e = s.size();
        if (e > b) names.push_back(s.substr(b, e - b));
        b = e + 1;
    }
    if (names.empty()) return std::nullopt;
    return names;
}

void Participants::on_participant_discovery(eprosima::fastdds::dds::DomainParticipant*,
                                            eprosima::fastrtps::rtps::ParticipantDiscoveryInfo&& info) {
    using Info = eprosima::fastrtps::rtps::ParticipantDiscoveryInfo;
    if (info.status != Info::DISCOVERED_PARTICIPANT && info.status != Info::CHANGED_QOS_PARTICIPANT) return;
    add(info.info.m_guid.guidPrefix, announced_members(info.info.m_userData.data_vec()));
}

void Participants::add(const GuidPrefix& p, std::optional<MemberNames> members) {
    const std::lock_guard<std::mutex> lock(mtx_);
    known_[p] = std::move(members);
    generation_.fetch_add(1, std::memory_order_release);
}

std::optional<MemberNames> Participants::members_of(const GuidPrefix& p) const {
    const std::lock_guard<std::mutex> lock(mtx_);
    const auto it = known_.find(p);
    return it == known_.end() ? std::nullopt : it->second;
}

bool Participants::knows(const GuidPrefix& p) const {
    const std::lock_guard<std::mutex> lock(mtx_);
    return known_.count(p) > 0;
}

bool Participants::announces(const std::string& name) const {
    const std::lock_guard<std::mutex> lock(mtx_);
    return std::any_of(known_.begin(), known_.end(), [&](const auto& kv) {
        return kv.second && std::find(kv.second->begin(), kv.second->end(), name) != kv.second->end();
    });
}

}  // namespace gdnav::dds
