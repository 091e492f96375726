#pragma once
// Who hosts which member (docs/protocol.md §2.5). Every gdnav participant announces the members it hosts in its
// USER_DATA QoS ("gdnav-members=nav_air,nav_att": member names have no comma), and keeps, from DDS participant
// discovery, what each participant of the domain announced, by GUID prefix; a data reader finds a sample's
// participant in the GUID prefix of the writer that SampleInfo names. A participant that announces nothing (another
// DDS vendor, a tool, a plain Fast DDS program) is known as such. Nothing here is a protection against a participant
// that lies: that is what DDS Security is for (§2.4); it keeps runs and tools that share a domain apart.
#include <atomic>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <fastdds/dds/domain/DomainParticipantListener.hpp>
#include <fastdds/rtps/common/GuidPrefix_t.hpp>

#include "dds/compat.hpp"

namespace gdnav::dds {

using GuidPrefix = eprosima::fastrtps::rtps::GuidPrefix_t;
using MemberNames = std::vector<std::string>;

// The USER_DATA bytes announcing `members` (empty: no announcement).
std::vector<unsigned char> announcement(const MemberNames& members);
// The members a USER_DATA announces; nullopt when it is not a gdnav announcement.
std::optional<MemberNames> announced_members(const std::vector<unsigned char>& user_data);

// The participants of the domain and what they announced: filled by Fast DDS's discovery thread (the listener of
// this process's participant), read by the data readers' threads.
class Participants final : public eprosima::fastdds::dds::DomainParticipantListener {
public:
    void on_participant_discovery(eprosima::fastdds::dds::DomainParticipant* participant,
                                  eprosima::fastrtps::rtps::ParticipantDiscoveryInfo&& info) override;
    // Participant p announced `members` (nullopt: nothing). Also for this process's own participant, whose writers
    // deliver to its own readers.
    void add(const GuidPrefix& p, std::optional<MemberNames> members);
    // What participant p announced: nullopt when it announced nothing or is not known.
    [[nodiscard]] std::optional<MemberNames> members_of(const GuidPrefix& p) const;
    // Whether participant p has been discovered (or added).
    [[nodiscard]] bool knows(const GuidPrefix& p) const;
    // Whether a known participant announced member `name`.
    [[nodiscard]] bool announces(const std::string& name) const;
    // Grows whenever what is known changes: decisions taken on what was known must then be taken again.
    [[nodiscard]] std::uint64_t generation() const { return generation_.load(std::memory_order_acquire); }

private:
    mutable std::mutex mtx_;
    std::map<GuidPrefix, std::optional<MemberNames>> known_;  // participants removed stay: their last samples may
                                                              // still be read
    std::atomic<std::uint64_t> generation_{0};
};

}  // namespace gdnav::dds
