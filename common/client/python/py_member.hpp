#pragma once
// gdnav_client.Member: a gdnav::client::Member whose step callback is a Python callable.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <pybind11/pybind11.h>

#include "gdnav/client/member.hpp"
#include "port.hpp"

namespace gdnav::pyclient {

// Cost of the Python step callback per call: wall time (what the run waits for, including time the process was
// preempted) and the calling thread's CPU time (the callback's own work), both with the GIL acquisition.
struct StepCost {
    std::uint64_t steps{0};
    double total_us{0.0}, max_us{0.0};
    double cpu_total_us{0.0}, cpu_max_us{0.0};
    void add(double wall_us, double cpu_us);
    [[nodiscard]] double mean_us() const { return steps ? total_us / static_cast<double>(steps) : 0.0; }
    [[nodiscard]] double cpu_mean_us() const { return steps ? cpu_total_us / static_cast<double>(steps) : 0.0; }
};

class PyMember {
public:
    explicit PyMember(client::Options opt);
    static std::unique_ptr<PyMember> from_args(const std::vector<std::string>& argv, const std::string& default_name);

    std::shared_ptr<Port> input(const std::string& topic, client::Lag lag);
    std::shared_ptr<Port> output(const std::string& topic);
    void on_step(pybind11::function fn) { step_fn_ = std::move(fn); }
    void on_finish(pybind11::function fn) { finish_fn_ = std::move(fn); }
    void publish_status(const std::string& message);
    // Joins the run with the GIL released; re-raises an exception of the step callback after the member has left.
    int run();

    [[nodiscard]] const client::Options& options() const { return opt_; }
    [[nodiscard]] const std::vector<std::string>& extra_args() const { return extra_; }
    [[nodiscard]] const StepCost& cost() const { return cost_; }
    [[nodiscard]] const client::StepInfo& step_info() const { return info_; }

private:
    void step(const client::StepInfo& s);  // GIL not held on entry

    client::Options opt_;
    std::vector<std::string> extra_;
    std::unique_ptr<client::Member> member_;
    std::shared_ptr<StepState> state_ = std::make_shared<StepState>();
    pybind11::object step_fn_;
    pybind11::object finish_fn_;
    client::StepInfo info_;
    StepCost cost_;
    bool ran_{false};
    std::thread::id run_thread_;                  // the thread that called run()
    std::vector<PyThreadState*> kept_states_;     // Python thread states of the host's listener threads
    std::optional<pybind11::error_already_set> error_;  // the step callback's exception, raised by run()
    std::string error_where_;
};

}  // namespace gdnav::pyclient
