#include "dds/filters/status_filter.hpp"

#include <string>

#include "dds/filters/cdr_filter.hpp"

namespace gdnav::dds {

using namespace eprosima::fastdds::dds;

namespace {

constexpr std::uint32_t kMemberOffset = 24;  // ComponentStatus.member after run_id, step (uint64) and t_s (double)

struct StatusFilter final : IContentFilter {
    std::string member;
    bool set(std::string_view p) {
        member = p;
        return !member.empty();
    }
    bool evaluate(const SerializedPayload& payload, const FilterSampleInfo&, const GUID_t&) const override {
        std::string_view m;
        if (!status_member_of_cdr(payload.data, payload.length, m)) return true;  // not ours to drop
        return m == member;
    }
};

}  // namespace

bool status_member_of_cdr(const unsigned char* data, std::uint32_t length, std::string_view& member) {
    std::uint64_t n = 0;  // string length, the terminating NUL included
    if (!cdr_filter::read_uint(data, length, kMemberOffset, 4, n)) return false;
    const std::uint32_t chars_at = cdr_filter::kEncapsulation + kMemberOffset + 4;
    if (n == 0 || n > length - chars_at) return false;
    member = std::string_view(reinterpret_cast<const char*>(data + chars_at), n - 1);
    return true;
}

void register_status_filter(DomainParticipant& participant) {
    static cdr_filter::Factory<StatusFilter> factory("status filter (a member name)");
    cdr_filter::register_factory(participant, kStatusFilterClass, factory,
                                 "hosts receive every member's status");
}

}  // namespace gdnav::dds
