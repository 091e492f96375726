#pragma once
// A content filter "the statuses of one member" for gdnav/ComponentStatus, evaluated by the writer like the stride
// filter (dds/filters/stride_filter.hpp): a member host needs only the clock's heartbeat from that topic, not the 10 Hz
// status of every other member (measured: docs/runtime.md, "Where a distributed step's time goes"), so its reader
// is a ContentFilteredTopic of class kStatusFilterClass with the member name as parameter. Every DdsContext
// registers the factory; a writer without it sends everything and the reader filters itself (same samples).
// The filter reads ComponentStatus.member from the CDR bytes: after run_id (uint64), step (uint64) and t_s (double),
// the string's length (uint32, NUL included) at offset 24 of the body and its characters from offset 28.
#include <cstdint>
#include <string_view>

#include <fastdds/dds/domain/DomainParticipant.hpp>

#include "dds/compat.hpp"

namespace gdnav::dds {

inline constexpr const char* kStatusFilterClass = "GDNAV_STATUS_OF_MEMBER";

// Registers the filter factory with the participant (once per participant, before any reader or writer).
void register_status_filter(eprosima::fastdds::dds::DomainParticipant& participant);

// The member name of a serialised ComponentStatus (CDR with its encapsulation header); false when malformed.
bool status_member_of_cdr(const unsigned char* data, std::uint32_t length, std::string_view& member);

}  // namespace gdnav::dds
