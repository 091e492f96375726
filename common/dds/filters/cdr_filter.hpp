#pragma once
// What gdnav's writer-side content filters share (dds/filters/stride_filter.hpp, dds/filters/status_filter.hpp): reading a
// field from a sample's CDR bytes, and a Fast DDS filter factory that makes one filter per ContentFilteredTopic from
// its single parameter. Each filter class is registered with every participant (DdsContext) before any endpoint.
#include <cstdint>
#include <string_view>

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/topic/IContentFilter.hpp>
#include <fastdds/dds/topic/IContentFilterFactory.hpp>
#include <spdlog/spdlog.h>

#include "dds/compat.hpp"

namespace gdnav::dds::cdr_filter {

inline constexpr std::uint32_t kEncapsulation = 4;  // CDR encapsulation header; its second byte tells the byte order

// The unsigned integer of `bytes` bytes (1-8) at `offset` of the body (after the encapsulation header), in the
// sample's byte order; false when the payload is too short.
inline bool read_uint(const unsigned char* data, std::uint32_t length, std::uint32_t offset, int bytes,
                      std::uint64_t& value) {
    if (data == nullptr || length < kEncapsulation + offset + static_cast<std::uint32_t>(bytes)) return false;
    const unsigned char* b = data + kEncapsulation + offset;
    const bool little = (data[1] & 1u) != 0;  // CDR_LE = 0x0001, CDR_BE = 0x0000
    value = 0;
    for (int i = 0; i < bytes; ++i) value = (value << 8) | b[little ? bytes - 1 - i : i];
    return true;
}

// F: an IContentFilter, default-constructible, with `bool set(std::string_view parameter)` (false = bad parameter).
template <class F>
struct Factory final : eprosima::fastdds::dds::IContentFilterFactory {
    using ReturnCode = eprosima::fastrtps::types::ReturnCode_t;
    const char* what;  // for the warning on a bad parameter
    explicit Factory(const char* w) : what(w) {}
    ReturnCode create_content_filter(const char*, const char*, const eprosima::fastdds::dds::TopicDataType*,
                                     const char*, const ParameterSeq& parameters,
                                     eprosima::fastdds::dds::IContentFilter*& filter) override {
        const std::string_view p = parameters.length() == 1 && parameters[0] ? parameters[0] : "";
        // A new filter from the parameter; a filter being re-parameterised is replaced only when it parses, so a
        // bad parameter leaves it as it was.
        auto* f = new F();
        if (parameters.length() != 1 || !f->set(p)) {
            spdlog::warn("{}: bad parameter '{}'", what, p);
            delete f;
            return ReturnCode::RETCODE_BAD_PARAMETER;
        }
        delete static_cast<F*>(filter);
        filter = f;
        return ReturnCode::RETCODE_OK;
    }
    ReturnCode delete_content_filter(const char*, eprosima::fastdds::dds::IContentFilter* filter) override {
        delete static_cast<F*>(filter);
        return ReturnCode::RETCODE_OK;
    }
};

// Registers `factory` (which must outlive the participant) under `filter_class`; warns when Fast DDS refuses it.
template <class F>
void register_factory(eprosima::fastdds::dds::DomainParticipant& participant, const char* filter_class,
                      Factory<F>& factory, const char* consequence) {
    if (participant.register_content_filter_factory(filter_class, &factory) !=
        eprosima::fastrtps::types::ReturnCode_t::RETCODE_OK)
        spdlog::warn("cannot register the content filter {}: {}", filter_class, consequence);
}

}  // namespace gdnav::dds::cdr_filter
