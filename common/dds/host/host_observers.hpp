#pragma once
// The DDS host's observers (docs/protocol.md §6.4): which members the host treats as observers, their readers (an
// input that may read a decimated mirror gets its reader once the member table names the producers, mirror.hpp),
// the mirrors every output writes for them, and the steps an observer gives up (lost samples, or it fell behind).
#include <cstdint>
#include <functional>
#include <vector>

#include <fastdds/dds/subscriber/DataReaderListener.hpp>

#include "dds/compat.hpp"
#include "dds/dds_context.hpp"
#include "dds/host/host_inbox.hpp"
#include "framework/run_config.hpp"
#include "msgs/messages.hpp"

namespace gdnav::dds::host {

// An observer as the host treats it (docs/protocol.md §6.4): observer() and no outputs to hold anybody up.
bool hosted_as_observer(const framework::Component& c);

// Gives `o` its mirror writer, with its matched-reader count kept up to date as well.
void add_mirror(Output& o, eprosima::fastdds::dds::DataWriter* mirror);
// Whether the mirror is due at step k: a mirror step, and somebody reads the mirror.
bool mirror_due(const Output& o, std::uint64_t k);
// How many of the output's readers read its mirror instead of the topic (they count as its readers in matching).
int mirror_readers(const Output& o);

// Observer `l` cannot compute step k any more: an input it reads at k has no sample of that step while a newer one
// of the same input has arrived (one writer's samples arrive in order, so the missing one was lost).
bool step_missed(const Local& l, std::uint64_t k);

// Observer `l` fell behind (paused, or a slow machine): a sample of step s of `ch` is beyond its inbox. It gives up
// the steps before the ones its inbox can hold with this sample, rather than dropping the samples it can still use.
void catch_up(Local& l, const Channel& ch, std::uint64_t s);

// The reader of an input on its topic itself (with the input's stride filter; best-effort for an observer).
eprosima::fastdds::dds::DataReader* topic_reader(DdsContext& dds, const Channel& ch, bool observer);

class Observers {
public:
    explicit Observers(const framework::RunConfig& rc) : rc_(rc) {}

    // Whether this run writes and reads mirrors (not in a secure run: a PKI grants each identity its own topics).
    [[nodiscard]] bool mirrors() const { return rc_.security_dir.empty(); }

    // Whether observer `l`'s input `in` waits for the member table for its reader (it may read a mirror).
    [[nodiscard]] bool defers(const Local& l, const framework::InputBase& in) const;

    // The readers of the deferred inputs, once the member table names the producers: the mirror when every producer
    // writes one, else the topic itself (with the stride filter). Each is served by listener_for(its channel).
    void make_readers(std::vector<Local>& locals, const std::vector<msg::MemberInfo>& table, DdsContext& dds,
                      const std::function<eprosima::fastdds::dds::DataReaderListener*(Channel&)>& listener_for) const;

    // The steps each observer computed and skipped (log lines at the end of the run).
    static void report(const std::vector<Local>& locals, std::uint64_t steps);

private:
    const framework::RunConfig& rc_;
};

}  // namespace gdnav::dds::host
