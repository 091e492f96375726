#include "dds/dds_context.hpp"

#include <cstdlib>
#include <stdexcept>

#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/log/Log.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>
#include <fastdds/dds/topic/ContentFilteredTopic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <spdlog/spdlog.h>

#include "dds/process/process_exit.hpp"
#include "dds/security/security.hpp"
#include "dds/filters/status_filter.hpp"
#include "dds/filters/stride_filter.hpp"

namespace gdnav::dds {

using namespace eprosima::fastdds::dds;

DdsContext::DdsContext(int domain_id, const std::filesystem::path& profile_file, const std::string& name,
                       const std::filesystem::path& security_dir, const std::string& identity,
                       const MemberNames& members) {
    auto* factory = DomainParticipantFactory::get_instance();
    // GDNAV_FASTDDS_LOG=warning|info: Fast DDS's own log at that verbosity (default: errors only).
    if (const char* v = std::getenv("GDNAV_FASTDDS_LOG")) {
        const std::string lv = v;
        if (lv == "warning") Log::SetVerbosity(Log::Kind::Warning);
        if (lv == "info") Log::SetVerbosity(Log::Kind::Info);
    }
    if (!std::filesystem::exists(profile_file))
        throw std::runtime_error("DDS profile file not found: " + profile_file.string());
    if (factory->load_XML_profiles_file(profile_file.string()) != ReturnCode_t::RETCODE_OK)
        throw std::runtime_error("cannot load DDS XML profiles from " + profile_file.string());
    DomainParticipantQos pq;
    if (factory->get_participant_qos_from_profile(kParticipantProfile, pq) != ReturnCode_t::RETCODE_OK)
        throw std::runtime_error("DDS profile file " + profile_file.string() + " has no participant profile '" +
                                 kParticipantProfile + "'");
    pq.name(name);
    // The material was checked by the process that started the run (launch/pki/identity_check.hpp).
    if (!security_dir.empty()) security::apply(pq, security_dir, identity);
    const auto user_data = announcement(members);
    pq.user_data().data_vec(std::vector<eprosima::fastrtps::rtps::octet>(user_data.begin(), user_data.end()));
    // The listener gets the discovery of participants only: every entity status goes to the entity's own listener or
    // condition, as without it.
    participant_ = factory->create_participant(static_cast<DomainId_t>(domain_id), pq, &participants_,
                                               StatusMask::none());
    if (!participant_)
        throw std::runtime_error("cannot create DDS participant on domain " + std::to_string(domain_id) +
                                 (security_dir.empty() ? std::string()
                                                       : " with security identity '" + identity + "' from " +
                                                             security_dir.string() + " (see the Fast DDS log above)"));
    participants_.add(participant_->guid().guidPrefix,
                      members.empty() ? std::nullopt : std::optional<MemberNames>(members));
    register_stride_filter(*participant_);  // before any writer: writers filter for strided readers
    register_status_filter(*participant_);  // and for status readers of one member
    publisher_ = participant_->create_publisher(PUBLISHER_QOS_DEFAULT);
    subscriber_ = participant_->create_subscriber(SUBSCRIBER_QOS_DEFAULT);
    if (!publisher_ || !subscriber_) throw std::runtime_error("cannot create DDS publisher/subscriber");
}

DdsContext::~DdsContext() {
    if (!participant_) return;
    // The participant's listener (participants_) dies with this object, and a kept participant goes on discovering
    // peers until the process ends: detached first, which waits for a discovery callback in progress. Readers and
    // writers go in any case (no listener of ours can be called after this); the participant itself stays in a
    // process that keeps it until it ends, which then leaves without a DISPOSE (dds/process/process_exit.hpp).
    participant_->set_listener(nullptr);
    participant_->delete_contained_entities();
    if (!participants_kept()) DomainParticipantFactory::get_instance()->delete_participant(participant_);
}

Topic* DdsContext::topic(const std::string& name, const msg::MessageOps& ops) {
    auto it = topics_.find(name);
    if (it != topics_.end()) return it->second;
    TypeSupport ts(ops.make_type());
    if (participant_->register_type(ts) != ReturnCode_t::RETCODE_OK)
        throw std::runtime_error("cannot register DDS type " + std::string(ops.type_name));
    Topic* t = participant_->create_topic(name, ts.get_type_name(), TOPIC_QOS_DEFAULT);
    if (!t) throw std::runtime_error("cannot create DDS topic " + name);
    topics_[name] = t;
    return t;
}

DataWriter* DdsContext::writer(const std::string& name, const msg::MessageOps& ops, const char* profile,
                               const char* fallback) {
    DataWriterQos defined;
    if (fallback != nullptr &&
        publisher_->get_datawriter_qos_from_profile(profile, defined) != ReturnCode_t::RETCODE_OK)
        profile = fallback;
    DataWriter* w = publisher_->create_datawriter_with_profile(topic(name, ops), profile);
    if (!w) throw std::runtime_error("cannot create DDS writer for " + name + " with profile '" + profile + "'");
    return w;
}

DataReader* DdsContext::reader(const std::string& name, const msg::MessageOps& ops, const char* profile,
                               std::uint64_t stride, bool best_effort) {
    if (stride <= 1) return create_reader(topic(name, ops), name, profile, best_effort);
    return filtered_reader(name, ops, profile, "/every_" + std::to_string(stride) + "_steps", "step % stride",
                           std::to_string(stride), kStrideFilterClass, best_effort);
}

bool DdsContext::delete_reader(DataReader* reader) {
    reader->set_listener(nullptr);
    const TopicDescription* description = reader->get_topicdescription();
    if (subscriber_->delete_datareader(reader) != ReturnCode_t::RETCODE_OK) return false;
    if (const auto* cft = dynamic_cast<const ContentFilteredTopic*>(description))
        participant_->delete_contentfilteredtopic(cft);
    return true;
}

DataReader* DdsContext::status_reader(const std::string& name, const msg::MessageOps& ops, const char* profile,
                                      const std::string& member) {
    return filtered_reader(name, ops, profile, "/of_" + member, "member = %0", member, kStatusFilterClass);
}

DataReader* DdsContext::filtered_reader(const std::string& name, const msg::MessageOps& ops, const char* profile,
                                        const std::string& suffix, const char* expression,
                                        const std::string& parameter, const char* filter_class,
                                        bool best_effort) {
    const std::string cft = name + suffix + "#" + std::to_string(++filtered_topics_);
    TopicDescription* description =
        participant_->create_contentfilteredtopic(cft, topic(name, ops), expression, {parameter}, filter_class);
    if (!description) throw std::runtime_error("cannot create the content-filtered topic " + cft);
    return create_reader(description, cft, profile, best_effort);
}

DataReader* DdsContext::create_reader(TopicDescription* description, const std::string& what, const char* profile,
                                      bool best_effort) {
    DataReader* r = nullptr;
    if (!best_effort) {
        r = subscriber_->create_datareader_with_profile(description, profile);
    } else {
        DataReaderQos q;
        if (subscriber_->get_datareader_qos_from_profile(profile, q) == ReturnCode_t::RETCODE_OK) {
            q.reliability().kind = BEST_EFFORT_RELIABILITY_QOS;
            r = subscriber_->create_datareader(description, q);
        }
    }
    if (!r)
        throw std::runtime_error("cannot create DDS " + std::string(best_effort ? "best-effort " : "") + "reader for " +
                                 what + " with profile '" + profile + "'");
    return r;
}

}  // namespace gdnav::dds
