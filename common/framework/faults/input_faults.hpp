#pragma once
// The scheduled faults of one input port, applied where its samples are delivered (docs/faults.md). Every consumer
// of a topic holds its own InputFaults and gets exactly the same faulted samples, because each fault is a pure
// function of (schedule, sample step, master seed, run index): loss and noise draw from the stream
// (seed, run index, target).child("fault<i>/<step>"), never from a stream whose state depends on the consumer.
//
//   drop     no sample (the input is not available at that step; its producer is not lost)
//   freeze   the last sample before the fault, re-stamped with the current step (a stuck sensor)
//   bias     the sample with constants added to named fields
//   noise    the sample with white Gaussian noise added to named fields
//   delay    the whole sample of N steps earlier, with its own stamp (a late message); none before step N
//   loss     no sample, with probability p at each step
//   nan      the sample with named fields set to NaN (a corrupt message)
//   kill     no sample and the input is lost (as when the producer dies), until the producer restarts
// Several faults active at one step act in list order (a drop or a loss ends the chain).
#include <cstdint>
#include <string>
#include <vector>

#include "framework/compat.hpp"
#include "random/stream.hpp"
#include "framework/component.hpp"
#include "framework/faults/fault_schedule.hpp"
#include "framework/fields/field_table.hpp"

namespace gdnav::framework::faults {

class InputFaults {
public:
    InputFaults(const FaultSchedule& schedule, const std::string& topic, std::vector<std::string> producers,
                const msg::MessageOps& ops, const RunInfo& run);
    ~InputFaults();
    InputFaults(const InputFaults&) = delete;
    InputFaults& operator=(const InputFaults&) = delete;

    // Takes on the faults of the schedule from index `first` on (faults injected live, adopted before they act).
    void extend(std::size_t first);

    [[nodiscard]] bool empty() const { return faults_.empty(); }
    // Every producer of the topic is killed at sample step j: there is no sample to wait for.
    [[nodiscard]] bool producer_killed(std::uint64_t j) const;

    struct Delivery {
        const void* data{nullptr};  // what the input is bound to (nullptr: not available)
        bool lost{false};           // the producer is dead (killed) at this step
    };
    // The sample of step j as consumers see it; `sample` is the sample published for step j (nullptr when the
    // producer is killed). Call in step order; calling again for the same step returns the same delivery.
    Delivery apply(std::uint64_t j, const void* sample);

private:
    struct Active {
        const Fault* fault;
        rnd::Stream stream;                                    // loss and noise: children per step
        std::vector<std::pair<const fields::Field*, std::vector<double>>> fields;  // bias and noise
        void* frozen{nullptr};                                 // freeze: the last sample before the fault
        bool have_frozen{false};
    };
    void* scratch();
    void add_to_fields(const Active& a, void* msg, std::uint64_t j);
    static void set_nan(const Active& a, void* msg);

    const FaultSchedule& schedule_;
    std::string topic_;
    std::vector<std::string> producers_;
    const msg::MessageOps& ops_;
    RunInfo run_;
    std::vector<Active> faults_;
    std::vector<void*> history_;            // delay: samples by step (ring)
    std::vector<std::uint64_t> history_step_;
    std::vector<bool> history_full_;
    void* out_{nullptr};                    // the faulted copy handed out
    std::uint64_t memo_step_{UINT64_MAX};
    Delivery memo_;
};

}  // namespace gdnav::framework::faults
