#include "runtime/status_filter.hpp"

#include <string>

#include <fastdds/dds/topic/IContentFilter.hpp>
#include <fastdds/dds/topic/IContentFilterFactory.hpp>
#include <spdlog/spdlog.h>

namespace gdnav::runtime {

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::types::ReturnCode_t;

namespace {

constexpr std::uint32_t kEncapsulation = 4;  // CDR encapsulation header
constexpr std::uint32_t kMemberOffset = 24;  // ComponentStatus.member after run_id, step (uint64) and t_s (double)

struct StatusFilter final : IContentFilter {
    std::string member;
    bool evaluate(const SerializedPayload& payload, const FilterSampleInfo&, const GUID_t&) const override {
        std::string_view m;
        if (!status_member_of_cdr(payload.data, payload.length, m)) return true;  // not ours to drop
        return m == member;
    }
};

struct StatusFilterFactory final : IContentFilterFactory {
    ReturnCode_t create_content_filter(const char*, const char*, const TopicDataType*, const char*,
                                       const ParameterSeq& parameters, IContentFilter*& filter) override {
        if (parameters.length() != 1 || parameters[0] == nullptr || parameters[0][0] == '\0') {
            spdlog::warn("status filter: one parameter expected, the member name");
            return ReturnCode_t::RETCODE_BAD_PARAMETER;
        }
        auto* f = filter ? static_cast<StatusFilter*>(filter) : new StatusFilter();
        f->member = parameters[0];
        filter = f;
        return ReturnCode_t::RETCODE_OK;
    }
    ReturnCode_t delete_content_filter(const char*, IContentFilter* filter) override {
        delete static_cast<StatusFilter*>(filter);
        return ReturnCode_t::RETCODE_OK;
    }
};

}  // namespace

bool status_member_of_cdr(const unsigned char* data, std::uint32_t length, std::string_view& member) {
    if (data == nullptr || length < kEncapsulation + kMemberOffset + 4) return false;
    const unsigned char* b = data + kEncapsulation + kMemberOffset;
    const bool little = (data[1] & 1u) != 0;  // CDR_LE = 0x0001, CDR_BE = 0x0000
    std::uint32_t n = 0;
    for (int i = 0; i < 4; ++i) n = (n << 8) | b[little ? 3 - i : i];
    // n counts the terminating NUL; the characters must fit in the payload
    if (n == 0 || n > length - (kEncapsulation + kMemberOffset + 4)) return false;
    member = std::string_view(reinterpret_cast<const char*>(b + 4), n - 1);
    return true;
}

void register_status_filter(DomainParticipant& participant) {
    static StatusFilterFactory factory;  // stateless; outlives every participant
    if (participant.register_content_filter_factory(kStatusFilterClass, &factory) != ReturnCode_t::RETCODE_OK)
        spdlog::warn("cannot register the status content filter: hosts receive every member's status");
}

}  // namespace gdnav::runtime
