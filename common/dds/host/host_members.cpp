#include "dds/host/host_members.hpp"

#include "framework/graph.hpp"

namespace gdnav::dds::host {

std::uint32_t MemberTable::index_of(const std::string& name) const {
    std::uint32_t index = UINT32_MAX;
    for (std::uint32_t i = 0; i < table_.size(); ++i)
        if (table_[i].name().to_string() == name) index = i;
    return index;
}

int MemberTable::readers_of(const std::string& topic) const {
    int n = 0;
    for (const auto& m : table_)
        for (const auto& t : framework::split_topics(m.inputs().to_string())) n += (t == topic);
    return n;
}

}  // namespace gdnav::dds::host
