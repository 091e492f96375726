#pragma once
// gdnav_client.Member: a gdnav::client::Member whose step callback is a Python callable.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "gdnav/client/member.hpp"
#include "bindings.hpp"
#include "port.hpp"
#include "step_call.hpp"

namespace gdnav::client::python {

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
    [[nodiscard]] const std::string& name() const { return opt_.name; }
    [[nodiscard]] std::uint64_t run_id() const { return opt_.run_id; }
    [[nodiscard]] StepView step_view() const { return {info_.dt_s, info_.last}; }

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
    std::optional<pybind11::error_already_set> error_;  // the step callback's exception, raised by run()
    std::string error_where_;
};

// gdnav_client.run_class: a member class as this process's member (docs/python.md, "Member classes").
int run_class(const pybind11::object& cls, const std::vector<std::string>& argv, const std::string& default_name);

}  // namespace gdnav::client::python
