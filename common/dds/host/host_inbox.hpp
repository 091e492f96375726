#pragma once
// The DDS host's records: the inbox of each input, the outputs and the local members (shared by the host's parts,
// host_impl.hpp), and the in-process hand-over between members hosted in the same process: a sample written by a
// local member goes straight into the inboxes of the local members that read it (a copy, no serialisation, no
// transport, no thread wake-up); it is published on DDS only while a reader outside the process is matched (another
// process's member, a recorder, a monitoring tool). An input whose producers are all in the process has no DDS reader
// (read_without_dds).
#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/DataWriterListener.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>

#include "dds/compat.hpp"
#include "dds/host/producer_check.hpp"
#include "dds/host/warn_limit.hpp"
#include "framework/component.hpp"
#include "framework/executor_access.hpp"
#include "framework/faults/input_faults.hpp"
#include "framework/lateness.hpp"
#include "framework/lockstep.hpp"

namespace gdnav::dds::host {

// Inbox of one input port: samples indexed by step (a ring of kInboxRing slots), or the latest sample for
// free-running producers. It owns its samples (the scratch sample DDS takes into, the latest, the ring's), and each
// of its fields has one writer, the member function named for what happens to the input: the member table sets its
// producers and faults (Inputs::configure), producers die and rejoin (mark_lost, revive), samples are filed into the
// ring (file_taken from DDS, file_copy from a local producer) or kept as the latest, rejections are counted.
class Channel {
public:
    // The inbox of input `in`: its samples created with the input's message operations.
    explicit Channel(framework::InputBase& in);
    ~Channel();
    Channel(const Channel&) = delete;
    Channel& operator=(const Channel&) = delete;

    [[nodiscard]] framework::InputBase* port() const { return port_; }
    [[nodiscard]] const msg::MessageOps& ops() const { return *ops_; }
    [[nodiscard]] eprosima::fastdds::dds::DataReader* reader() const { return reader_; }
    // An observer's input: its reader is made at CONFIGURE (host_observers.hpp).
    [[nodiscard]] bool deferred() const { return deferred_; }
    // Every producer of the input is a member of this process: it has no DDS reader (drop_reader), its samples come
    // only by hand-over (route_locally).
    [[nodiscard]] bool local_only() const { return local_only_; }
    // Raised by its reader's listener when a sample arrives (host_impl.hpp); take_fresh() lowers it and says whether
    // it was raised, before the reader is taken from, so that a sample arriving meanwhile raises it again.
    [[nodiscard]] std::atomic<bool>* fresh_flag() { return &fresh_; }
    bool take_fresh() { return fresh_.exchange(false); }

    // Set-up. The member was created anew (a scheduled restart): the inbox serves its new port, lost as before.
    void rebind(framework::InputBase& fresh) {
        port_ = &fresh;
        if (lost_) framework::ExecutorAccess::set_lost(*port_, true);
    }
    void set_reader(eprosima::fastdds::dds::DataReader* reader) { reader_ = reader; }
    void defer_reader() { deferred_ = true; }
    // From the member table: every producer is in this process. Returns the reader to delete (nullptr: none made).
    eprosima::fastdds::dds::DataReader* drop_reader() {
        local_only_ = true;
        deferred_ = false;
        return std::exchange(reader_, nullptr);
    }

    // From the member table: the producers of the topic (their table indices and names; announce[i]: producer i is
    // started by gdnav, producer_check.hpp), and whether they run free (then the input keeps the latest sample).
    // A free input stays free.
    void set_producers(std::vector<std::uint32_t> indices, MemberNames names, std::vector<bool> announce,
                       const Participants* known, bool runs_free) {
        producers_ = std::move(indices);
        free_ = free_ || runs_free;
        producer_.configure(std::move(names), std::move(announce), known);
    }
    // The scheduled faults on this input (nullptr: none).
    void set_faults(std::unique_ptr<framework::faults::InputFaults> f) { faults_ = std::move(f); }
    [[nodiscard]] const std::vector<std::uint32_t>& producers() const { return producers_; }
    [[nodiscard]] const ProducerCheck& producer() const { return producer_; }
    // Whether a sample written by a writer of participant p is a producer's (the check caches its decisions).
    bool from_producer(const GuidPrefix& p) { return producer_.accepts(p); }
    [[nodiscard]] bool free() const { return free_; }
    [[nodiscard]] framework::faults::InputFaults* faults() const { return faults_.get(); }

    // Every producer was declared dead (or none exists): the input is lost, its port too.
    void mark_lost() {
        lost_ = true;
        framework::ExecutorAccess::set_lost(*port_, true);
    }
    // A producer rejoined and computes from step from_step: samples of the steps before are lost, the ring is
    // emptied (its samples are of the time before the producer died), the port is found again at from_step.
    void revive(std::uint64_t from_step) {
        lost_ = false;
        revived_ = true;
        lost_until_ = from_step;
        full_.fill(false);
    }
    [[nodiscard]] bool lost() const { return lost_; }
    [[nodiscard]] bool revived() const { return revived_; }
    [[nodiscard]] std::uint64_t lost_until() const { return lost_until_; }

    // Where DDS takes the next sample into.
    [[nodiscard]] void* scratch() const { return scratch_; }
    // A free input's sample (copied): the one its member's steps use from now on.
    void keep_latest(const void* sample) {
        ops_->copy(latest_, sample);
        has_latest_ = true;
    }
    [[nodiscard]] bool has_latest() const { return has_latest_; }
    [[nodiscard]] void* latest() const { return latest_; }
    // The sample of step s DDS took into scratch() becomes ring slot i's (swapped, not copied); a non-finite t_s
    // keeps it as bad, so that the step does not wait for it: the input is not available at that step.
    void file_taken(std::size_t i, std::uint64_t s, bool finite) {
        std::swap(slot_[i], scratch_);
        slot_step_[i] = s;
        full_[i] = true;
        bad_[i] = !finite;
    }
    // A local producer's sample of step s, copied into ring slot i (hand_over below).
    void file_copy(std::size_t i, const void* sample, std::uint64_t s) {
        ops_->copy(slot_[i], sample);
        slot_step_[i] = s;
        full_[i] = true;
        bad_[i] = false;
    }
    // Whether ring slot i holds the sample of step s; whether that sample is bad (a non-finite t_s); the sample.
    [[nodiscard]] bool holds(std::size_t i, std::uint64_t s) const { return full_[i] && slot_step_[i] == s; }
    [[nodiscard]] bool bad(std::size_t i) const { return bad_[i]; }
    [[nodiscard]] void* slot(std::size_t i) const { return slot_[i]; }

    // A sample of step s arrived (any step; an observer's lost-step test reads it).
    void saw(std::uint64_t s) {
        if (!seen_ || s > newest_) newest_ = s;
        seen_ = true;
    }
    // Whether a sample of a step after s has arrived.
    [[nodiscard]] bool saw_after(std::uint64_t s) const { return seen_ && newest_ > s; }

    // A free input's step used that was `late` steps old (-1: none was there yet).
    void note_lateness(std::int64_t late) { lateness_.add(late); }
    [[nodiscard]] const framework::Lateness& lateness() const { return lateness_; }

    // Rejected samples, counted at wall time now_s: the number of them the warning to log now stands for (0: none
    // to log now, warn_limit.hpp).
    std::uint64_t reject_foreign(double now_s) { return foreign_.occur(now_s); }
    std::uint64_t reject_stamp(double now_s) { return bad_stamp_.occur(now_s); }
    std::uint64_t drop_too_far(double now_s) { return too_far_local_.occur(now_s); }
    [[nodiscard]] const WarnLimit& foreign() const { return foreign_; }
    [[nodiscard]] const WarnLimit& bad_stamp() const { return bad_stamp_; }
    [[nodiscard]] const WarnLimit& too_far_local() const { return too_far_local_; }

private:
    framework::InputBase* port_;
    eprosima::fastdds::dds::DataReader* reader_{nullptr};
    const msg::MessageOps* ops_;
    void* scratch_;
    std::array<void*, framework::kInboxRing> slot_{};
    std::array<std::uint64_t, framework::kInboxRing> slot_step_{};
    std::array<bool, framework::kInboxRing> full_{};
    std::array<bool, framework::kInboxRing> bad_{};
    void* latest_;
    bool has_latest_{false};
    std::vector<std::uint32_t> producers_;  // member indices in the table
    bool free_{false};                      // produced by a free-running member
    bool lost_{false};                      // every producer declared dead
    framework::Lateness lateness_;          // free channels: how late the samples used were
    std::unique_ptr<framework::faults::InputFaults> faults_;
    std::uint64_t lost_until_{0};  // its producer rejoined: samples of steps below this one are lost
    bool revived_{false};
    bool deferred_{false};
    bool local_only_{false};
    std::atomic<bool> fresh_{true};
    bool seen_{false};             // a sample has arrived (any step)
    std::uint64_t newest_{0};      // the newest step of the samples arrived
    ProducerCheck producer_;       // whose samples are used (from the member table)
    WarnLimit foreign_;            // samples dropped: not written by a producer of the topic
    WarnLimit bad_stamp_;          // samples rejected: non-finite t_s, or a step beyond the run or the inbox
    WarnLimit too_far_local_;      // samples of a producer of this process beyond the inbox of a local reader
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
    framework::OutputBase* port{nullptr};
    eprosima::fastdds::dds::DataWriter* writer{nullptr};
    std::vector<Route> routes;  // local readers (those with a DDS reader are matched too: not outside ones)
    std::unique_ptr<MatchCount> matched;  // listener of `writer` (outlives it: the host deletes DDS first)
    // The decimated mirror of the topic for observers (host_observers.hpp; nullptr: none) and its readers.
    eprosima::fastdds::dds::DataWriter* mirror{nullptr};
    std::unique_ptr<MatchCount> mirror_matched;
};

// The matched-reader count of `writer`, kept up to date from now on (the listener must outlive the writer).
std::unique_ptr<MatchCount> count_matches(eprosima::fastdds::dds::DataWriter* writer);
// An output of a local member: its writer, with the matched-reader count kept up to date.
Output make_output(framework::OutputBase* port, eprosima::fastdds::dds::DataWriter* writer);

struct Local {
    framework::Component* comp{nullptr};
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

// Whether member `name` is one of this process's members.
bool hosted_here(const std::vector<Local>& locals, const std::string& name);

// Connects every local output to the local inputs of its topic (call once, after all locals are set up).
void route_locally(std::vector<Local>& locals);

// Hands `sample` (of step s) to local reader `r`: copied into its inbox. Returns false when the reader's ring
// cannot take it (too far ahead: dropped, as a DDS sample would be).
bool hand_over(const Route& r, const Local& consumer, const void* sample, std::uint64_t s);

// Whether a reader outside the process is matched with this output's writer (then the sample is also published).
bool read_outside(const Output& o);

// How many of this output's local readers have a DDS reader (matched with its writer like an outside one).
int local_dds_readers(const Output& o);

// Whether an input whose producers are `producers` is read without DDS: every one is a member of this process
// (`here`). Such an input gets its samples by hand-over only; a DDS reader of its own would also be matched with the
// local writer and, whenever the topic is also read outside the process, receive every sample a second time through
// Fast DDS's intraprocess delivery (docs/runtime.md, "Members: what a step costs").
bool read_without_dds(const MemberNames& producers, const std::function<bool(const std::string&)>& here);

}  // namespace gdnav::dds::host
