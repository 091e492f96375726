#include "py_member.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <csignal>
#include <stdexcept>
#include <thread>

#include <spdlog/spdlog.h>

namespace py = pybind11;

namespace gdnav::pyclient {

namespace {

// Member::run() installs the runtime's SIGINT/SIGTERM handlers; give Python its own back afterwards.
class SignalGuard {
public:
    SignalGuard() {
        sigaction(SIGINT, nullptr, &int_);
        sigaction(SIGTERM, nullptr, &term_);
    }
    ~SignalGuard() {
        sigaction(SIGINT, &int_, nullptr);
        sigaction(SIGTERM, &term_, nullptr);
    }
    SignalGuard(const SignalGuard&) = delete;
    SignalGuard& operator=(const SignalGuard&) = delete;

private:
    struct sigaction int_ {};
    struct sigaction term_ {};
};

double thread_cpu_us() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return 1e6 * static_cast<double>(ts.tv_sec) + 1e-3 * static_cast<double>(ts.tv_nsec);
}

}  // namespace

void StepCost::add(double wall_us, double cpu_us) {
    ++steps;
    total_us += wall_us;
    max_us = std::max(max_us, wall_us);
    cpu_total_us += cpu_us;
    cpu_max_us = std::max(cpu_max_us, cpu_us);
}

PyMember::PyMember(client::Options opt) : opt_(std::move(opt)), member_(std::make_unique<client::Member>(opt_)) {}

std::unique_ptr<PyMember> PyMember::from_args(const std::vector<std::string>& argv, const std::string& default_name) {
    std::vector<const char*> args;
    for (const auto& a : argv) args.push_back(a.c_str());
    std::vector<std::string> extra;
    auto m = std::make_unique<PyMember>(
        client::Options::from_args(static_cast<int>(args.size()), args.data(), default_name, &extra));
    m->extra_ = std::move(extra);
    return m;
}

std::shared_ptr<Port> PyMember::input(const std::string& topic, client::Lag lag) {
    if (ran_) throw std::logic_error("Member.input(): declare ports before run()");
    return std::make_shared<Port>(member_->input_any(topic, lag), state_);
}

std::shared_ptr<Port> PyMember::output(const std::string& topic) {
    if (ran_) throw std::logic_error("Member.output(): declare ports before run()");
    return std::make_shared<Port>(member_->output_any(topic));
}

void PyMember::publish_status(const std::string& message) { member_->publish_status(message); }

void PyMember::step(const client::StepInfo& s) {
    if (error_) return;  // leaving the run: the outputs keep their last values
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = thread_cpu_us();
    std::string failure;
    {
        // The host calls the step from whichever thread received the sample (its own or a Fast DDS listener
        // thread). Each listener thread keeps its Python thread state for the whole run (deleted by run()): without
        // the extra reference, pybind11 would create and destroy one per call, which is costly (docs/python.md).
        py::gil_scoped_acquire gil;
        thread_local bool kept = false;
        if (!kept && std::this_thread::get_id() != run_thread_) {
            gil.inc_ref();
            kept_states_.push_back(PyThreadState_Get());
            kept = true;
        }
        info_ = s;
        state_->in_step = true;
        try {
            if (step_fn_) step_fn_(s.k, s.t_s);
        } catch (py::error_already_set& e) {
            error_where_ = "in the step callback of member '" + opt_.name + "' at step " + std::to_string(s.k) +
                           " (t = " + std::to_string(s.t_s) + " s)";
            failure = "Python exception in the step callback: " + std::string(e.what());
            error_.emplace(std::move(e));
        }
        state_->in_step = false;
    }
    const double cpu_us = thread_cpu_us() - cpu0;
    cost_.add(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count(), cpu_us);
    // The host leaves the run the regular way: it logs the error's first line, sends it to the clock
    // (STATUS_ERROR: the clock declares this member dead with that reason), finishes and returns exit code 1;
    // run() then re-raises the Python exception.
    if (!failure.empty()) throw std::runtime_error(failure);
}

int PyMember::run() {
    if (ran_) throw std::logic_error("Member.run() may be called once");
    ran_ = true;
    member_->on_step([this](const client::StepInfo& s) { step(s); });
    if (finish_fn_)
        member_->on_finish([this](bool completed) {
            py::gil_scoped_acquire gil;
            try {
                finish_fn_(completed);
            } catch (py::error_already_set& e) {
                spdlog::error("Python exception in the finish callback of member '{}': {}", opt_.name, e.what());
                if (!error_) error_.emplace(std::move(e));
            }
        });
    int code = 0;
    run_thread_ = std::this_thread::get_id();
    {
        SignalGuard signals;
        py::gil_scoped_release release;
        code = member_->run();
    }
    // The host has stopped its listener threads: their Python thread states go (a thread state left behind
    // blocks the interpreter's shutdown).
    for (PyThreadState* ts : kept_states_) {
        PyThreadState_Clear(ts);
        PyThreadState_Delete(ts);
    }
    kept_states_.clear();
    spdlog::info("member '{}': Python step callback, {} steps: CPU mean {:.1f} us, max {:.1f} us; wall mean {:.1f} "
                 "us, max {:.1f} us per step", opt_.name, cost_.steps, cost_.cpu_mean_us(), cost_.cpu_max_us,
                 cost_.mean_us(), cost_.max_us);
    if (error_) {
        py::error_already_set e = std::move(*error_);
        error_.reset();
        if (!error_where_.empty() && py::hasattr(e.value(), "add_note")) e.value().attr("add_note")(error_where_);
        throw e;
    }
    return code;
}

}  // namespace gdnav::pyclient
