#pragma once
// Type-erased operations on IDL message types, so executors and the recorder can move, stamp and serialise
// samples of any topic without knowing their C++ type.
//
// This header declares them; it names no DDS type support. message_ops<T>() is defined once per type, in the message
// library that owns the type, by GDNAV_DECLARE_MESSAGE(Type, PubSubType) (msgs/message_ops_impl.hpp): every gdnav
// topic in msgs/messages.cpp, the viewer's Foxglove types in msgs/viewer_messages.cpp. A component that includes
// this header (through framework/component.hpp) therefore compiles without Fast DDS.
#include <cstdint>
#include <vector>

namespace eprosima::fastdds::dds {
class TopicDataType;
}

namespace gdnav::msg {

struct MessageOps {
    const char* type_name;
    // A new type support object for DDS topics (owned by the caller).
    eprosima::fastdds::dds::TopicDataType* (*make_type)();
    void* (*create)();
    void (*destroy)(void*);
    void (*copy)(void* dst, const void* src);
    // Sets stamp (run id, step, time) on samples that carry one (no-op otherwise).
    void (*set_stamp)(void* sample, std::uint64_t run_id, std::uint64_t step, double t_s);
    // Step and run of a stamped sample (UINT64_MAX for unstamped types).
    std::uint64_t (*step_of)(const void* sample);
    std::uint64_t (*run_of)(const void* sample);
    // CDR encoding with zeroed padding: identical samples give identical bytes.
    void (*serialize)(const void* sample, std::vector<std::uint8_t>& out);
    // Decodes n bytes of CDR (with the encapsulation header) into `sample`; false when they are not a sample.
    bool (*deserialize)(const std::uint8_t* bytes, std::uint32_t n, void* sample);
    // Simulated time of a stamped sample (0 for unstamped types).
    double (*time_of)(const void* sample);
};

// The operations of message type T; defined by GDNAV_DECLARE_MESSAGE in the type's message library.
template <class T>
const MessageOps& message_ops();

}  // namespace gdnav::msg

// Their names in gdnav::runtime, kept for existing external members (framework/compat.hpp, docs/external.md).
namespace gdnav::runtime {
using ::gdnav::msg::message_ops;
using ::gdnav::msg::MessageOps;
}  // namespace gdnav::runtime
