#pragma once
// A content filter "every N-th step" for gdnav's data topics, evaluated by the writer: a reader whose input has a
// stride N > 1 (InputBase::stride) reads a ContentFilteredTopic of filter class kStrideFilterClass with the
// parameter N, and every gdnav participant registers the factory, so the producers' writers send only the samples
// of steps k % N == 0 (for the others Fast DDS 2.9 sends one GAP per delivered sample, so only some strides pay:
// docs/notes/runtime-measurements.md, "Which strides pay"). A writer without the factory (another DDS vendor, a
// participant that did not register it) sends every sample, and the reader applies the same filter itself: it gets
// the same samples.
// An observer's input at a stride that is a multiple of 10 reads a decimated mirror instead where every producer
// writes one (dds/host/mirror.hpp: cheaper on the wire); the filter serves every other strided input: a barrier
// member's, an observer's whose producer is external or not a gdnav host, and every strided input of a secure run.
// The filter reads SampleStamp.step from the CDR bytes: every data topic starts with `SampleStamp stamp`
// (run_id: uint64, step: uint64), so the step is the 8 bytes at offset 8 of the body, after the 4-byte
// encapsulation header whose second byte tells the byte order.
#include <cstdint>

#include <fastdds/dds/domain/DomainParticipant.hpp>

#include "dds/compat.hpp"

namespace gdnav::dds {

inline constexpr const char* kStrideFilterClass = "GDNAV_STEP_STRIDE";

// Registers the filter factory with the participant (once per participant, before any reader or writer).
void register_stride_filter(eprosima::fastdds::dds::DomainParticipant& participant);

// The step of a serialised data sample (CDR with its encapsulation header); false when too short to hold a stamp.
bool stamp_step_of_cdr(const unsigned char* data, std::uint32_t length, std::uint64_t& step);

}  // namespace gdnav::dds
