// The Python module gdnav_client: Python bindings of gdnav::client (common/client/include/gdnav/client/member.hpp).
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "py_member.hpp"

namespace py = pybind11;
using gdnav::client::Lag;
using gdnav::client::Options;
using gdnav::client::python::Port;
using gdnav::client::python::PyMember;

namespace {

constexpr const char* kDoc = R"doc(gdnav_client: join a gdnav run as a lockstep member from Python (docs/python.md).

    import numpy as np, sys, gdnav_client as g
    m = g.Member("nav_att", domain=7, run=0, free_running=False)  # or g.Member.from_args(sys.argv, "nav_att")
    imu = m.input("gdnav/ImuSample")                               # lag=g.Lag.Same (default) or g.Lag.Previous
    pos = m.input("gdnav/PositionEstimate", lag=g.Lag.Previous)
    att = m.output("gdnav/AttitudeEstimate")
    def step(k, t_s):                       # every step k, at simulated time t_s [s]
        if not imu.available(): return      # e.g. its producer was declared dead (imu.lost())
        f = imu["f_b_mps2"]                 # numpy float64 array (a copy); scalars are float, int or bool
        att["q_nb"] = np.array([1.0, 0.0, 0.0, 0.0])
    m.on_step(step)
    sys.exit(m.run())

The run must have been started with `gdnav run ... --external NAME --domain D`. Member(name, domain=0, run=0,
free_running=False, dds_profile="", startup_timeout_s=120.0, log_level="info", security=""); Member.from_args(argv,
default_name) reads --name, --domain, --run, --free-running, --dds-profile, --security, --startup-timeout, --log-level
and leaves arguments
starting with --x- in Member.extra_args; without a flag it takes the name, domain, run id, security directory and DDS
profile from the environment of a member started by gdnav (GDNAV_MEMBER, GDNAV_DOMAIN, GDNAV_RUN, GDNAV_SECURITY,
GDNAV_DDS_PROFILE; gdnav run --member).

Ports (declare them before run(); topics "gdnav/<Type>" of idl/gdnav.idl, nested fields as "stamp.t_s"):
  port[field], port[field] = value, port.as_dict(), port.update(dict), port.fields(), port.available(),
  port.lost(), port.topic, port.is_output.
  Inputs are bound to the sample of step k (Lag.Same) or k-1 (Lag.Previous; none at k = 0) and can be read only
  inside the step callback. Outputs keep their value between steps; the host publishes every output after every
  callback, stamped with (run id, k, t_s) (stamp.* fields are read-only). Arrays are assigned from any sequence of
  exactly the field's length.
  Errors: an unknown topic raises ValueError (naming the known topics); an unknown field KeyError (naming the
  topic's fields and their types); an array of the wrong length ValueError; a value of the wrong type TypeError;
  reading an input without a sample RuntimeError.

Member.on_step(fn(k, t_s)) sets the step callback: the GIL is held only while it runs (Member.dt_s and Member.last
describe the current step); Member.on_finish(fn(completed)) is called once after the run; Member.publish_status(str)
publishes a notice on ComponentStatus (shown in the clock's log). Member.run() joins the run with the GIL released
and returns the exit code: 0 completed, 3 aborted by the clock, 4 lost the clock, 5 no clock / protocol mismatch,
130 interrupted. An exception raised by the step callback makes the member leave the run at once (the clock
declares it dead; the run goes on without it unless it is essential), then run() re-raises it. The callback's own
cost per call (GIL acquisition included) is logged after the run and kept in Member.step_cost: {"steps",
"cpu_mean_us", "cpu_max_us"} (CPU time of the calling thread: the callback's own work) and {"mean_us", "max_us"}
(wall time: what the run waits for, including preemption by other processes). One Member.run() per process.
)doc";

}  // namespace

PYBIND11_MODULE(gdnav_client, mod) {
    mod.doc() = kDoc;
    gdnav::client::python::bind_ports(mod);

    py::class_<PyMember> member(mod, "Member", "a lockstep member of a gdnav run (see the module docstring)");
    member.def(py::init([](std::string name, int domain, std::uint64_t run, bool free_running, std::string dds_profile,
                         double startup_timeout_s, std::string log_level, std::string security) {
                 Options o;
                 o.name = std::move(name);
                 o.domain_id = domain;
                 o.run_id = run;
                 o.free_running = free_running;
                 o.dds_profile = dds_profile;
                 o.startup_timeout_s = startup_timeout_s;
                 o.log_level = std::move(log_level);
                 o.security = security;
                 return std::make_unique<PyMember>(std::move(o));
             }),
             py::arg("name"), py::arg("domain") = 0, py::arg("run") = 0, py::arg("free_running") = false,
             py::arg("dds_profile") = "", py::arg("startup_timeout_s") = 120.0, py::arg("log_level") = "info",
             py::arg("security") = "")
        .def_static("from_args", &PyMember::from_args, py::arg("argv"), py::arg("default_name"))
        .def("on_step", &PyMember::on_step, py::arg("fn"))
        .def("on_finish", &PyMember::on_finish, py::arg("fn"))
        .def("run", &PyMember::run)
        .def_property_readonly("domain", [](const PyMember& m) { return m.options().domain_id; })
        .def_property_readonly("free_running", [](const PyMember& m) { return m.options().free_running; })
        .def_property_readonly("extra_args", &PyMember::extra_args);
    gdnav::client::python::bind_member_calls(member);
    mod.def("run_class", &gdnav::client::python::run_class, py::arg("cls"), py::arg("argv"), py::arg("default_name"),
            "run a member class (docs/python.md) as this process's member: m = Member.from_args(argv, "
            "default_name); obj = cls(m); obj.step(k, t_s) every step, obj.finish(completed) if defined; returns "
            "m.run()");
}
