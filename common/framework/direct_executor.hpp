#pragma once
// Direct layout: every component in one thread, called in graph order, inputs bound straight to the producers'
// output buffers (Lag::Previous inputs to a copy of step k-1). No transport, no allocation per step.
// Scheduled faults (set_faults): inputs pass through framework/faults/input_faults.hpp; a killed member is not
// stepped; a restarted one is created anew with the factory and bound in place of the old one.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "framework/compat.hpp"
#include "framework/component.hpp"
#include "framework/faults/fault_schedule.hpp"
#include "framework/faults/input_faults.hpp"

namespace gdnav::framework {

class DirectExecutor {
public:
    using Factory = std::function<std::unique_ptr<Component>(const std::string& name)>;
    DirectExecutor(std::vector<std::unique_ptr<Component>> components, const RunInfo& run);
    ~DirectExecutor();
    // Applies a fault schedule (kept by reference: it must outlive the executor); `rebuild` creates a member
    // restarted by a fault (needed only when the schedule restarts one).
    void set_faults(const faults::FaultSchedule& schedule, Factory rebuild);
    // Runs steps [0, run.steps). `progress(k)` is called every `progress_every` steps and may return false to stop
    // the run early (components then finish with completed = false). Returns the steps executed.
    std::uint64_t run(const std::function<bool(std::uint64_t)>& progress = {}, std::uint64_t progress_every = 1000);
    // Runs a single step k (for tests and benchmarks).
    void step(std::uint64_t k);
    void finish(bool completed);
    [[nodiscard]] const std::vector<Component*>& order() const { return order_; }
    // Measures the wall time of every component's step (for `gdnav bench`; off by default).
    void enable_profiling() { profile_ns_.assign(order_.size(), 0); }
    // Mean wall time per step of each component in order(), in microseconds (empty unless profiling).
    [[nodiscard]] std::vector<double> mean_step_us(std::uint64_t steps) const;

private:
    struct PrevBuffer {
        OutputBase* source;
        void* copy;
        bool valid;
    };
    struct Binding {
        InputBase* input;
        OutputBase* producer;           // Lag::Same: the producer's live buffer
        PrevBuffer* previous;           // Lag::Previous
        faults::InputFaults* faults;    // nullptr: no fault on this input
    };
    void bind_all();
    void restart(std::size_t i, std::uint64_t k);

    std::vector<std::unique_ptr<Component>> owned_;
    std::vector<Component*> order_;
    std::vector<std::vector<Binding>> bindings_;  // per component in order_
    std::map<std::string, std::unique_ptr<PrevBuffer>> prev_;  // by topic
    std::map<std::string, std::unique_ptr<faults::InputFaults>> input_faults_;  // by "consumer/input index"
    const faults::FaultSchedule* schedule_{nullptr};
    Factory rebuild_;
    std::vector<bool> killed_;  // per component in order_: not stepped at the current step
    RunInfo run_;
    bool finished_{false};
    std::vector<std::int64_t> profile_ns_;
};

}  // namespace gdnav::framework
