#include "bindings.hpp"

namespace py = pybind11;

namespace gdnav::client::python {

ClassCallbacks class_callbacks(const py::handle& obj) {
    const std::string cls = py::str(py::type::handle_of(obj).attr("__qualname__"));
    if (!py::hasattr(obj, "step") || !PyCallable_Check(obj.attr("step").ptr()))
        throw py::type_error("class " + cls + " has no method step(self, k, t_s)");
    ClassCallbacks cb{py::reinterpret_borrow<py::function>(py::object(obj.attr("step"))), py::none()};
    if (py::hasattr(obj, "finish")) {
        cb.finish = obj.attr("finish");
        if (!PyCallable_Check(cb.finish.ptr())) throw py::type_error("class " + cls + ": finish is not a method");
    }
    return cb;
}

void bind_ports(py::module_& mod) {
    py::enum_<framework::Lag>(mod, "Lag", "input lag: Same = the sample of step k, Previous = of step k-1")
        .value("Same", framework::Lag::Same)
        .value("Previous", framework::Lag::Previous);

    py::class_<Port, std::shared_ptr<Port>>(mod, "Port", "an input or output of a member (see the module docstring)")
        .def("__getitem__", &Port::get, py::arg("field"))
        .def("__setitem__", &Port::set, py::arg("field"), py::arg("value"))
        .def("as_dict", &Port::as_dict, "all fields as {name: value}")
        .def("update", &Port::update, py::arg("values"), "set the fields of an output from {name: value}")
        .def("fields", &Port::fields, "[(name, IDL type)]")
        .def("available", &Port::available, "an input has a sample at this step (outputs: always)")
        .def("lost", &Port::lost, "the input's producer was declared dead")
        .def_property_readonly("topic", &Port::topic)
        .def_property_readonly("is_output", &Port::is_output)
        .def("__repr__", [](const Port& p) { return std::string(p.is_output() ? "<output " : "<input ") + p.topic() + ">"; });
}

}  // namespace gdnav::client::python
