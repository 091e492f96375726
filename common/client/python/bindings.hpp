#pragma once
// Python bindings shared by the module gdnav_client (external members, module.cpp) and the in-process host
// (common/client/embed): the same Lag, Port and member calls in both.
#include <cstdint>
#include <memory>
#include <string>

#include <pybind11/pybind11.h>

#include "framework/component.hpp"
#include "port.hpp"
#include "step_call.hpp"

namespace gdnav::client::python {

// What a step callback sees of the current step.
struct StepView {
    double dt_s{0.01};
    bool last{false};
};

// The callbacks of a member object made from a member class (docs/python.md, "Member classes"): its step(k, t_s)
// method, and finish(completed) when it has one (else None). Raises TypeError naming the class when step is
// missing or not callable.
struct ClassCallbacks {
    pybind11::function step;
    pybind11::object finish;
};
ClassCallbacks class_callbacks(const pybind11::handle& obj);

// Lag and Port into `mod`.
void bind_ports(pybind11::module_& mod);

// The member calls both hosts share: input, output, publish_status, name, run_id, dt_s, last, step_cost. M has
// input(topic, Lag), output(topic), publish_status(text), name(), run_id(), step_view() and cost().
template <class M, class... Options>
void bind_member_calls(pybind11::class_<M, Options...>& cls) {
    namespace py = pybind11;
    cls.def("input", &M::input, py::arg("topic"), py::arg("lag") = framework::Lag::Same, py::keep_alive<0, 1>())
        .def("output", &M::output, py::arg("topic"), py::keep_alive<0, 1>())
        .def("publish_status", &M::publish_status, py::arg("message"))
        .def_property_readonly("name", [](const M& m) { return m.name(); })
        .def_property_readonly("run_id", [](const M& m) { return m.run_id(); })
        .def_property_readonly("dt_s", [](const M& m) { return m.step_view().dt_s; })
        .def_property_readonly("last", [](const M& m) { return m.step_view().last; })
        .def_property_readonly("step_cost", [](const M& m) { return m.cost().as_dict(); });
}

}  // namespace gdnav::client::python
