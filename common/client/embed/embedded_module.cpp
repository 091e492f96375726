// The module gdnav_client inside gdnav (the embedded interpreter's built-in module): what a member class imports.
#include <pybind11/embed.h>

#include "client/python/bindings.hpp"
#include "framework/run_members.hpp"
#include "python_component.hpp"
#include "python_member.hpp"

namespace py = pybind11;

PYBIND11_EMBEDDED_MODULE(gdnav_client, mod) {
    mod.doc() = "gdnav_client inside gdnav: the ports and member calls of an in-process member class (docs/python.md)";
    gdnav::client::python::bind_ports(mod);
    py::class_<gdnav::client::embed::Host, std::shared_ptr<gdnav::client::embed::Host>> host(
        mod, "Member", "the member an in-process member class is constructed with (docs/python.md)");
    gdnav::client::python::bind_member_calls(host);
    mod.def("run_class", [](const py::args&, const py::kwargs&) {
        throw std::runtime_error("gdnav_client.run_class() runs an external member; inside gdnav, the class runs as "
                                 "run.members NAME: {python: {file, class}} (docs/python.md)");
    });
}

namespace gdnav::client::embed {

void register_python_member(framework::ComponentRegistry& reg) {
    reg.add(framework::kPythonMemberType,
            "a member class in Python, run in the gdnav process (run.members: {NAME: {python: {file, class}}}; "
            "docs/python.md)",
            [&reg](const std::string& name) { return std::make_unique<PythonComponent>(name, reg); });
}

}  // namespace gdnav::client::embed
