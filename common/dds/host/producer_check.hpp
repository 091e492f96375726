#pragma once
// Whether a sample of an input comes from a producer that the member table names for its topic (docs/protocol.md
// §2.5), by the participant of the writer: accepted from a participant that announced one of the producers
// (dds/participants.hpp); from a participant that announced nothing only for a producer that may be a member of
// another DDS vendor (one that gdnav does not start: external or a joiner) and that no known participant announces.
// A producer that gdnav starts always announces itself, so a participant that announces nothing never passes for it,
// not even before the producer's own participant is discovered. Decisions are cached by participant and taken again
// when discovery learns something new.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "dds/compat.hpp"
#include "dds/participants.hpp"

namespace gdnav::dds::host {

class ProducerCheck {
public:
    // producers: the names the member table gives for the topic; must_announce[i]: producer i is started by gdnav.
    void configure(MemberNames producers, std::vector<bool> must_announce, const Participants* known);
    // Whether the member table is known (before it, nobody's sample can be needed).
    [[nodiscard]] bool configured() const { return known_ != nullptr; }
    // Whether a sample written by a writer of participant p may be used.
    bool accepts(const GuidPrefix& p) {
        const std::uint64_t g = known_->generation();
        if (g != generation_) {
            decided_.clear();
            generation_ = g;
        }
        for (const auto& [q, ok] : decided_)
            if (q == p) return ok;
        decided_.emplace_back(p, decide(p));
        return decided_.back().second;
    }
    // The producers' names, for messages ("sensors_air", "a, b").
    [[nodiscard]] std::string names() const;

private:
    [[nodiscard]] bool decide(const GuidPrefix& p) const;

    MemberNames producers_;
    std::vector<bool> must_announce_;
    const Participants* known_{nullptr};
    std::uint64_t generation_{UINT64_MAX};
    std::vector<std::pair<GuidPrefix, bool>> decided_;  // for the participants' generation_
};

}  // namespace gdnav::dds::host
