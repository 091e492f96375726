#include "runtime/stride_filter.hpp"

#include <charconv>
#include <cstring>
#include <string_view>

#include <fastdds/dds/topic/IContentFilter.hpp>
#include <fastdds/dds/topic/IContentFilterFactory.hpp>
#include <spdlog/spdlog.h>

namespace gdnav::runtime {

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::types::ReturnCode_t;

namespace {

constexpr std::uint32_t kEncapsulation = 4;  // CDR encapsulation header
constexpr std::uint32_t kStepOffset = 8;     // SampleStamp.step after SampleStamp.run_id (uint64)

struct StrideFilter final : IContentFilter {
    std::uint64_t stride{1};
    bool evaluate(const SerializedPayload& payload, const FilterSampleInfo&, const GUID_t&) const override {
        std::uint64_t step = 0;
        if (!stamp_step_of_cdr(payload.data, payload.length, step)) return true;  // not ours to drop
        return step % stride == 0;
    }
};

struct StrideFilterFactory final : IContentFilterFactory {
    ReturnCode_t create_content_filter(const char*, const char*, const TopicDataType*, const char*,
                                       const ParameterSeq& parameters, IContentFilter*& filter) override {
        std::uint64_t n = 0;
        if (parameters.length() != 1) return ReturnCode_t::RETCODE_BAD_PARAMETER;
        const std::string_view p = parameters[0] ? parameters[0] : "";
        const auto r = std::from_chars(p.data(), p.data() + p.size(), n);
        if (r.ec != std::errc() || r.ptr != p.data() + p.size() || n == 0) {
            spdlog::warn("stride filter: bad parameter '{}' (a positive integer)", p);
            return ReturnCode_t::RETCODE_BAD_PARAMETER;
        }
        auto* f = filter ? static_cast<StrideFilter*>(filter) : new StrideFilter();
        f->stride = n;
        filter = f;
        return ReturnCode_t::RETCODE_OK;
    }
    ReturnCode_t delete_content_filter(const char*, IContentFilter* filter) override {
        delete static_cast<StrideFilter*>(filter);
        return ReturnCode_t::RETCODE_OK;
    }
};

}  // namespace

bool stamp_step_of_cdr(const unsigned char* data, std::uint32_t length, std::uint64_t& step) {
    if (data == nullptr || length < kEncapsulation + kStepOffset + 8) return false;
    const unsigned char* b = data + kEncapsulation + kStepOffset;
    const bool little = (data[1] & 1u) != 0;  // CDR_LE = 0x0001, CDR_BE = 0x0000
    step = 0;
    for (int i = 0; i < 8; ++i) step = (step << 8) | b[little ? 7 - i : i];
    return true;
}

void register_stride_filter(DomainParticipant& participant) {
    static StrideFilterFactory factory;  // stateless; outlives every participant
    if (participant.register_content_filter_factory(kStrideFilterClass, &factory) != ReturnCode_t::RETCODE_OK)
        spdlog::warn("cannot register the stride content filter: readers with a stride receive every sample");
}

}  // namespace gdnav::runtime
