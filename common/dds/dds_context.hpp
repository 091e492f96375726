#pragma once
// One DDS participant per process, created from the XML profiles in config/dds/ (loaded explicitly: Fast DDS 2.9
// silently ignores FASTRTPS_DEFAULT_PROFILES_FILE unless profiles are loaded before the default QoS is read).
// With a security directory the participant authenticates and encrypts (DDS Security). Topics and types are
// registered once; entities are deleted in the destructor so shared memory is released. The participant announces
// the members it hosts and learns what the others announce (dds/participants.hpp).
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>

#include "dds/compat.hpp"
#include "dds/participants.hpp"
#include "msgs/message_ops.hpp"

namespace gdnav::dds {

// Profile names defined in config/dds/gdnav_profiles.xml.
inline constexpr const char* kParticipantProfile = "gdnav_participant";
inline constexpr const char* kDataWriterProfile = "gdnav_data_writer";
inline constexpr const char* kDataReaderProfile = "gdnav_data_reader";
inline constexpr const char* kControlWriterProfile = "gdnav_control_writer";
// The members' StepDone and ComponentStatus writers (the clock's Tick and status writers take kControlWriterProfile).
// Optional in a profile file: where it is missing, kControlWriterProfile (DdsContext::writer's fallback).
inline constexpr const char* kMemberControlWriterProfile = "gdnav_member_control_writer";
inline constexpr const char* kControlReaderProfile = "gdnav_control_reader";
inline constexpr const char* kLatchedWriterProfile = "gdnav_latched_writer";
inline constexpr const char* kLatchedReaderProfile = "gdnav_latched_reader";

class DdsContext {
public:
    // security_dir empty: a plain participant; else DDS Security on with `identity` (dds/security/security.hpp).
    // members: the members this participant hosts, announced in its USER_DATA (none: it announces nothing).
    DdsContext(int domain_id, const std::filesystem::path& profile_file, const std::string& name,
               const std::filesystem::path& security_dir = {}, const std::string& identity = {},
               const MemberNames& members = {});
    ~DdsContext();
    DdsContext(const DdsContext&) = delete;
    DdsContext& operator=(const DdsContext&) = delete;

    // fallback: the profile used when the profile file does not define `profile` (nullptr: none, an error).
    eprosima::fastdds::dds::DataWriter* writer(const std::string& topic, const msg::MessageOps& ops,
                                               const char* profile, const char* fallback = nullptr);
    // stride > 1: the reader gets only the samples of steps k % stride == 0, filtered by the writers where they can
    // (dds/filters/stride_filter.hpp). best_effort: the profile's QoS with BEST_EFFORT reliability (an observer's
    // inputs, Component::observer(): no acknowledgements or resends, a lost sample stays lost).
    eprosima::fastdds::dds::DataReader* reader(const std::string& topic, const msg::MessageOps& ops,
                                               const char* profile, std::uint64_t stride = 1, bool best_effort = false);
    // A reader of `topic` (ComponentStatus) that gets only the statuses of `member` (dds/filters/status_filter.hpp).
    eprosima::fastdds::dds::DataReader* status_reader(const std::string& topic, const msg::MessageOps& ops,
                                                      const char* profile, const std::string& member);
    // Deletes a reader made by reader() (its listener removed first) and its content-filtered topic, if any. False
    // when Fast DDS refuses (the reader then stays, unread).
    bool delete_reader(eprosima::fastdds::dds::DataReader* reader);
    [[nodiscard]] eprosima::fastdds::dds::DomainParticipant* participant() const { return participant_; }
    // The participants of the domain and the members they announced (this one's own included).
    [[nodiscard]] const Participants& participants() const { return participants_; }

private:
    eprosima::fastdds::dds::Topic* topic(const std::string& name, const msg::MessageOps& ops);
    // A reader of a ContentFilteredTopic of `name` (named name + suffix + a counter) with one filter parameter.
    eprosima::fastdds::dds::DataReader* filtered_reader(const std::string& name, const msg::MessageOps& ops,
                                                        const char* profile, const std::string& suffix,
                                                        const char* expression, const std::string& parameter,
                                                        const char* filter_class, bool best_effort = false);
    eprosima::fastdds::dds::DataReader* create_reader(eprosima::fastdds::dds::TopicDescription* description,
                                                      const std::string& what, const char* profile,
                                                      bool best_effort = false);
    Participants participants_;  // the participant's listener (the destructor detaches it first)
    eprosima::fastdds::dds::DomainParticipant* participant_{nullptr};
    eprosima::fastdds::dds::Publisher* publisher_{nullptr};
    eprosima::fastdds::dds::Subscriber* subscriber_{nullptr};
    std::map<std::string, eprosima::fastdds::dds::Topic*> topics_;
    unsigned filtered_topics_{0};  // content-filtered topics need names unique in the participant
};

}  // namespace gdnav::dds
