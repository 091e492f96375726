#pragma once
// One call into Python from a C++ thread that does not hold the GIL (a host's loop or a Fast DDS listener thread):
// shared by the external Python member (py_member.cpp) and the in-process one (common/client/embed).
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>

namespace gdnav::client::python {

// Cost of the Python step callback per call: wall time (what the run waits for, including time the process was
// preempted) and the calling thread's CPU time (the callback's own work), both with the GIL acquisition.
struct StepCost {
    std::uint64_t steps{0};
    double total_us{0.0}, max_us{0.0};
    double cpu_total_us{0.0}, cpu_max_us{0.0};
    void add(double wall_us, double cpu_us);
    [[nodiscard]] double mean_us() const { return steps ? total_us / static_cast<double>(steps) : 0.0; }
    [[nodiscard]] double cpu_mean_us() const { return steps ? cpu_total_us / static_cast<double>(steps) : 0.0; }
    [[nodiscard]] pybind11::dict as_dict() const;
    // "N steps: CPU mean .. us, max .. us; wall mean .. us, max .. us per step"
    [[nodiscard]] std::string text() const;  // {"steps", "mean_us", "max_us", "cpu_mean_us", "cpu_max_us"}
};

// Holds the GIL for its lifetime (one acquisition) and adds its wall and CPU time to `cost` when it ends.
// A thread Python has never seen (a listener thread) gets a thread state that it keeps until
// release_kept_thread_states(): creating and deleting one per call would cost hundreds of microseconds.
class StepCall {
public:
    explicit StepCall(StepCost& cost);
    ~StepCall();
    StepCall(const StepCall&) = delete;
    StepCall& operator=(const StepCall&) = delete;

private:
    StepCost& cost_;
    std::chrono::steady_clock::time_point t0_;
    double cpu0_us_;
    std::optional<pybind11::gil_scoped_acquire> gil_;
};

// Deletes the thread states StepCall kept (GIL held; the threads they belong to have ended or will not call again).
void release_kept_thread_states();

}  // namespace gdnav::client::python
