#include "step_call.hpp"

#include <algorithm>
#include <ctime>
#include <vector>

#include <spdlog/fmt/fmt.h>

namespace gdnav::client::python {

namespace {

double thread_cpu_us() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return 1e6 * static_cast<double>(ts.tv_sec) + 1e-3 * static_cast<double>(ts.tv_nsec);
}

// Thread states kept by StepCall (guarded by the GIL).
std::vector<PyThreadState*>& kept_states() {
    static std::vector<PyThreadState*> v;
    return v;
}

}  // namespace

void StepCost::add(double wall_us, double cpu_us) {
    ++steps;
    total_us += wall_us;
    max_us = std::max(max_us, wall_us);
    cpu_total_us += cpu_us;
    cpu_max_us = std::max(cpu_max_us, cpu_us);
}

pybind11::dict StepCost::as_dict() const {
    pybind11::dict d;
    d["steps"] = steps;
    d["mean_us"] = mean_us();
    d["max_us"] = max_us;
    d["cpu_mean_us"] = cpu_mean_us();
    d["cpu_max_us"] = cpu_max_us;
    return d;
}

std::string StepCost::text() const {
    return fmt::format("{} steps: CPU mean {:.1f} us, max {:.1f} us; wall mean {:.1f} us, max {:.1f} us per step", steps,
                       cpu_mean_us(), cpu_max_us, mean_us(), max_us);
}

StepCall::StepCall(StepCost& cost)
    : cost_(cost), t0_(std::chrono::steady_clock::now()), cpu0_us_(thread_cpu_us()) {
    // Read before taking the GIL: whether Python already knows this thread (the thread that started the
    // interpreter or called run() does; so does one whose state is kept).
    thread_local bool kept = false;
    const bool known = kept || PyGILState_GetThisThreadState() != nullptr;
    gil_.emplace();
    if (!known) {
        gil_->inc_ref();  // pybind11 keeps the state while its count is above zero
        kept_states().push_back(PyThreadState_Get());
        kept = true;
    }
}

StepCall::~StepCall() {
    gil_.reset();
    const double cpu_us = thread_cpu_us() - cpu0_us_;
    cost_.add(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0_).count(), cpu_us);
}

void release_kept_thread_states() {
    for (PyThreadState* ts : kept_states()) {
        PyThreadState_Clear(ts);
        PyThreadState_Delete(ts);
    }
    kept_states().clear();
}

}  // namespace gdnav::client::python
