#pragma once
// The DDS host's inputs: the inbox of every input port of its members (host_inbox.hpp), filled from DDS by step,
// bound to the ports when a step runs; inputs whose producers are all dead are lost, and found again when a
// producer rejoins; faults scheduled on an input pass through it; free-running inputs keep their lateness.
// Only the producers' samples are used (producer_check.hpp); the others, and samples with a bad stamp, are rejected
// and counted (docs/protocol.md §3.5).
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "dds/compat.hpp"
#include "dds/host/host_inbox.hpp"
#include "framework/faults/fault_schedule.hpp"
#include "msgs/messages.hpp"

namespace gdnav::dds::host {

class Inputs {
public:
    // free_running: the host's own members run free (their inputs use the latest samples and are not a deadline).
    explicit Inputs(bool free_running) : free_running_(free_running) {}
    Inputs(const Inputs&) = delete;
    Inputs& operator=(const Inputs&) = delete;

    // Where the participants of the domain are known, and which producers are started by gdnav (they announce
    // themselves: producer_check.hpp). Call before configure().
    void identify(const Participants* known, std::function<bool(const std::string&)> must_announce);
    // The inbox of input port `in`, its samples allocated; its reader is set by the caller.
    Channel* add(framework::InputBase* in);
    // Every reader made so far.
    [[nodiscard]] std::vector<eprosima::fastdds::dds::DataReader*> readers() const;

    // From the clock's member table: the producers of each of member l's inputs, and the scheduled faults on them
    // (`schedule`, none when empty); an input nobody produces is lost.
    void configure(const Local& l, const std::vector<msg::MemberInfo>& table,
                   const framework::faults::FaultSchedule& schedule, const framework::RunInfo& ri);
    // Whether every input's reader is matched with all its producers (an input read without DDS needs none).
    [[nodiscard]] bool matched() const;

    // The samples that arrived for member l's input `ch` (of run ri), into its inbox by step; others' samples and
    // bad stamps are rejected.
    void read(Local& l, Channel& ch, const framework::RunInfo& ri);
    // Binds member l's inputs for step k. False when a sample it waits for is not here yet.
    bool ready(const Local& l, std::uint64_t k) const;
    // Free inputs of a step about to run: how many steps old the sample used is (once per executed step).
    void record_lateness(const Local& l, std::uint64_t k) const;
    // A sample of step s of a producer in this process beyond the inbox of member l's input ch: dropped, with a
    // (rate-limited) warning.
    static void warn_too_far(const Local& l, Channel& ch, std::uint64_t s);

    // The clock declared producers dead (bit = table index): inputs whose producers are all dead are lost.
    void apply_dead_mask(std::uint64_t dead_mask);
    // Producer `i` (named `name`) rejoined at step from_step: its lost inputs wait for its samples from then on.
    void revive(std::uint32_t i, const std::string& name, std::uint64_t from_step);
    // A longer fault schedule (faults from index `first` are new): inputs take on the new faults.
    void extend_faults(const framework::faults::FaultSchedule& schedule, std::size_t first,
                       const std::vector<msg::MemberInfo>& table, const framework::RunInfo& ri);

    // Free-running inputs (hardware-in-the-loop): summary lines and <out>/lateness/<member>.yaml.
    void report_lateness(const std::vector<Local>& locals, const std::string& out_dir) const;
    // The end of the run: one line per input that rejected samples, with the totals.
    static void report_rejected(const std::vector<Local>& locals);

private:
    // A sample of a participant that is not a producer of ch's topic (dropped); one with a bad stamp (`why`).
    static void reject_foreign(const Local& l, Channel& ch, const GuidPrefix& from, std::uint64_t s);
    static void reject_stamp(const Local& l, Channel& ch, std::uint64_t s, double t_s, const char* why);

    bool free_running_{false};
    const Participants* known_{nullptr};
    std::function<bool(const std::string&)> must_announce_;
    std::vector<std::unique_ptr<Channel>> channels_;
};

}  // namespace gdnav::dds::host
