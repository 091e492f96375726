#include "py_member.hpp"

#include <algorithm>
#include <csignal>
#include <stdexcept>

#include <spdlog/spdlog.h>

namespace py = pybind11;

namespace gdnav::client::python {

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

}  // namespace

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
    std::string failure;
    {
        StepCall call(cost_);  // the GIL, from whichever thread the host calls in (docs/python.md)
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
    {
        SignalGuard signals;
        py::gil_scoped_release release;
        code = member_->run();
    }
    // The host has stopped its listener threads: their Python thread states go (a thread state left behind
    // blocks the interpreter's shutdown).
    release_kept_thread_states();
    spdlog::info("member '{}': Python step callback, {}", opt_.name, cost_.text());
    if (error_) {
        py::error_already_set e = std::move(*error_);
        error_.reset();
        if (!error_where_.empty() && py::hasattr(e.value(), "add_note")) e.value().attr("add_note")(error_where_);
        throw e;
    }
    return code;
}

int run_class(const py::object& cls, const std::vector<std::string>& argv, const std::string& default_name) {
    py::object m = py::cast(PyMember::from_args(argv, default_name));
    const ClassCallbacks cb = class_callbacks(cls(m));
    auto& member = m.cast<PyMember&>();
    member.on_step(cb.step);
    if (!cb.finish.is_none()) member.on_finish(cb.finish.cast<py::function>());
    return member.run();
}

}  // namespace gdnav::client::python
