#pragma once
// Direct layout: every component in one thread, called in graph order, inputs bound straight to the producers'
// output buffers (Lag::Previous inputs to a copy of step k-1). No transport, no allocation per step.
#include <functional>
#include <memory>
#include <vector>

#include "runtime/component.hpp"

namespace gdnav::runtime {

class DirectExecutor {
public:
    DirectExecutor(std::vector<std::unique_ptr<Component>> components, const RunInfo& run);
    ~DirectExecutor();
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
        const void* same;      // producer's live buffer (Lag::Same)
        PrevBuffer* previous;  // Lag::Previous
    };
    std::vector<std::unique_ptr<Component>> owned_;
    std::vector<Component*> order_;
    std::vector<std::vector<Binding>> bindings_;  // per component in order_
    std::vector<std::unique_ptr<PrevBuffer>> prev_;
    RunInfo run_;
    bool finished_{false};
    std::vector<std::int64_t> profile_ns_;
};

}  // namespace gdnav::runtime
