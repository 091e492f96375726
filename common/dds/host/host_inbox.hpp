#pragma once
// The DDS host's records: the inbox of each input, the outputs and the local members (shared by the host's parts,
// host_impl.hpp), and the in-process hand-over between members hosted in the same process: a sample written by a
// local member goes straight into the inboxes of the local members that read it (a copy, no serialisation, no
// transport, no thread wake-up); it is published on DDS only while a reader outside the process is matched (another
// process's member, a recorder, a monitoring tool).
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/DataWriterListener.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>

#include "dds/host/producer_check.hpp"
#include "dds/host/warn_limit.hpp"
#include "framework/component.hpp"
#include "framework/faults/input_faults.hpp"
#include "framework/lateness.hpp"
#include "framework/lockstep.hpp"

namespace gdnav::runtime::host {

// Inbox of one input port: samples indexed by step (ring), or the latest sample for free-running producers.
struct Channel {
    InputBase* port{nullptr};
    eprosima::fastdds::dds::DataReader* reader{nullptr};
    const MessageOps* ops{nullptr};
    void* scratch{nullptr};
    std::array<void*, kInboxRing> slot{};
    std::array<std::uint64_t, kInboxRing> slot_step{};
    std::array<bool, kInboxRing> full{};
    std::array<bool, kInboxRing> bad{};    // its sample had a non-finite t_s: the input is not available at that step
    void* latest{nullptr};
    bool has_latest{false};
    std::vector<std::uint32_t> producers;  // member indices in the table
    bool free{false};                      // produced by a free-running member
    bool lost{false};                      // every producer declared dead
    Lateness lateness;                     // free channels: how late the samples used were
    std::unique_ptr<faults::InputFaults> faults;  // scheduled faults on this input (nullptr: none)
    std::uint64_t lost_until{0};  // its producer rejoined: samples of steps below this one are lost
    bool revived{false};
    bool deferred{false};         // an observer's input: its reader is made at CONFIGURE (host_observers.hpp)
    bool seen{false};             // a sample has arrived (any step)
    std::uint64_t newest{0};      // the newest step of the samples arrived (an observer's lost-step test)
    ProducerCheck producer;       // whose samples are used (from the member table)
    WarnLimit foreign;            // samples dropped: not written by a producer of the topic
    WarnLimit bad_stamp;          // samples rejected: non-finite t_s, or a step beyond the run or the inbox
    WarnLimit too_far_local;      // samples of a producer of this process beyond the inbox of a local reader
    void saw(std::uint64_t s) {
        if (!seen || s > newest) newest = s;
        seen = true;
    }
};

// Where a local member's output goes inside the process: the inboxes of the local members that read its topic.
struct Route {
    std::size_t consumer{0};  // index into the host's locals
    Channel* channel{nullptr};
};

// The matched-reader count of a writer, kept by Fast DDS's matching callback (so the step does not ask for it).
struct MatchCount final : eprosima::fastdds::dds::DataWriterListener {
    std::atomic<int> readers{0};
    void on_publication_matched(eprosima::fastdds::dds::DataWriter*,
                                const eprosima::fastdds::dds::PublicationMatchedStatus& st) override {
        readers.store(st.current_count);
    }
};

struct Output {
    OutputBase* port{nullptr};
    eprosima::fastdds::dds::DataWriter* writer{nullptr};
    std::vector<Route> routes;  // local readers (their DDS readers are matched too: not counted as outside ones)
    std::unique_ptr<MatchCount> matched;  // listener of `writer` (outlives it: the host deletes DDS first)
    // The decimated mirror of the topic for observers (host_observers.hpp; nullptr: none) and its readers.
    eprosima::fastdds::dds::DataWriter* mirror{nullptr};
    std::unique_ptr<MatchCount> mirror_matched;
};

// The matched-reader count of `writer`, kept up to date from now on (the listener must outlive the writer).
std::unique_ptr<MatchCount> count_matches(eprosima::fastdds::dds::DataWriter* writer);
// An output of a local member: its writer, with the matched-reader count kept up to date.
Output make_output(OutputBase* port, eprosima::fastdds::dds::DataWriter* writer);

struct Local {
    Component* comp{nullptr};
    std::uint32_t index{0};
    std::uint64_t next_step{0};
    bool killed{false};            // stopped by a scheduled kill (not stepped until its restart)
    bool awaiting_rejoin{false};   // --rejoin: not stepped before the clock assigns its first step
    std::uint64_t restarted_at{UINT64_MAX};
    std::vector<Channel*> inputs;
    std::vector<Output> outputs;
    bool observer{false};          // Component::observer(): not in the barrier, best-effort inputs, skips lost steps
    // In the clock's barrier (reports StepDone): not a member of a free-running host, not an observer.
    bool barrier{true};
    std::uint64_t skipped{0};      // observer: steps not computed (a sample lost, or too late for the inbox)
};

// Ring index for a sample of step s in `ch`, read by a member whose next step is next_step: kOlder when no step of
// the member needs it any more, kTooFar when it is beyond the ring.
inline constexpr long kOlder = -1;
inline constexpr long kTooFar = -2;
long inbox_index(const Channel& ch, std::uint64_t next_step, std::uint64_t s);

// What member l's inputs rejected so far, for its heartbeat (docs/protocol.md §3.1): "" when nothing, else
// "rejected TOPIC:NOT_FROM_PRODUCER:BAD_STAMP,..." for each input that rejected any.
std::string rejected_note(const Local& l);

// Connects every local output to the local inputs of its topic (call once, after all locals are set up).
void route_locally(std::vector<Local>& locals);

// Hands `sample` (of step s) to local reader `r`: copied into its inbox. Returns false when the reader's ring
// cannot take it (too far ahead: dropped, as a DDS sample would be).
bool hand_over(const Route& r, const Local& consumer, const void* sample, std::uint64_t s);

// Whether a reader outside the process is matched with this output's writer (then the sample is also published).
bool read_outside(const Output& o);

}  // namespace gdnav::runtime::host
