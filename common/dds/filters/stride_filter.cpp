#include "dds/filters/stride_filter.hpp"

#include <charconv>

#include "dds/filters/cdr_filter.hpp"

namespace gdnav::dds {

using namespace eprosima::fastdds::dds;

namespace {

constexpr std::uint32_t kStepOffset = 8;  // SampleStamp.step after SampleStamp.run_id (uint64)

struct StrideFilter final : IContentFilter {
    std::uint64_t stride{1};
    bool set(std::string_view p) {
        const auto r = std::from_chars(p.data(), p.data() + p.size(), stride);
        return r.ec == std::errc() && r.ptr == p.data() + p.size() && stride > 0;
    }
    bool evaluate(const SerializedPayload& payload, const FilterSampleInfo&, const GUID_t&) const override {
        std::uint64_t step = 0;
        if (!stamp_step_of_cdr(payload.data, payload.length, step)) return true;  // not ours to drop
        return step % stride == 0;
    }
};

}  // namespace

bool stamp_step_of_cdr(const unsigned char* data, std::uint32_t length, std::uint64_t& step) {
    return cdr_filter::read_uint(data, length, kStepOffset, 8, step);
}

void register_stride_filter(DomainParticipant& participant) {
    static cdr_filter::Factory<StrideFilter> factory("stride filter (a positive integer)");
    cdr_filter::register_factory(participant, kStrideFilterClass, factory,
                                 "readers with a stride receive every sample");
}

}  // namespace gdnav::dds
