#include "dds/host/producer_check.hpp"

#include <algorithm>

namespace gdnav::dds::host {

void ProducerCheck::configure(MemberNames producers, std::vector<bool> must_announce, const Participants* known) {
    producers_ = std::move(producers);
    must_announce_ = std::move(must_announce);
    must_announce_.resize(producers_.size(), false);
    known_ = known;
    generation_ = UINT64_MAX;
    decided_.clear();
}

bool ProducerCheck::decide(const GuidPrefix& p) const {
    if (const auto members = known_->members_of(p))
        return std::any_of(producers_.begin(), producers_.end(), [&](const std::string& n) {
            return std::find(members->begin(), members->end(), n) != members->end();
        });
    for (std::size_t i = 0; i < producers_.size(); ++i)
        if (!must_announce_[i] && !known_->announces(producers_[i])) return true;
    return false;
}

std::string ProducerCheck::names() const {
    std::string s;
    for (const auto& n : producers_) s += (s.empty() ? "" : ", ") + n;
    return s;
}

}  // namespace gdnav::dds::host
