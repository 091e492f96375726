#pragma once
// The clock's member table as the DDS host keeps it (docs/protocol.md §3): the members of the run, adopted from the
// clock's CONFIGURE, and which of them the clock declared dead (its Ticks' dead mask, bit = table index) less those
// that rejoined.
#include <cstdint>
#include <string>
#include <vector>

#include "dds/compat.hpp"
#include "msgs/messages.hpp"

namespace gdnav::dds::host {

class MemberTable {
public:
    // The table of the CONFIGURE the host joined with.
    void adopt(const std::vector<msg::MemberInfo>& members) { table_.assign(members.begin(), members.end()); }
    [[nodiscard]] const std::vector<msg::MemberInfo>& entries() const { return table_; }
    // Index of member `name`, UINT32_MAX when absent.
    [[nodiscard]] std::uint32_t index_of(const std::string& name) const;
    // Readers of `topic` the table announces.
    [[nodiscard]] int readers_of(const std::string& topic) const;

    // A Tick's dead mask: returns true when it declares dead a member not dead so far (rejoined ones do not count).
    bool declare_dead(std::uint64_t tick_mask) {
        const std::uint64_t dead = tick_mask & ~revived_mask_;
        if ((dead | dead_mask_) == dead_mask_) return false;
        dead_mask_ |= dead;
        return true;
    }
    // Members the clock declared dead (bit = table index), less those that rejoined.
    [[nodiscard]] std::uint64_t dead_mask() const { return dead_mask_; }
    // Member i came back: its old dead bit no longer counts.
    void revive(std::uint32_t i) {
        revived_mask_ |= 1ULL << i;
        dead_mask_ &= ~(1ULL << i);
    }

private:
    std::vector<msg::MemberInfo> table_;
    std::uint64_t dead_mask_{0};
    std::uint64_t revived_mask_{0};  // members that rejoined: their old dead bit no longer counts
};

}  // namespace gdnav::dds::host
