#include "python_component.hpp"

#include <filesystem>
#include <mutex>
#include <set>
#include <stdexcept>

#include <pybind11/embed.h>
#include <spdlog/spdlog.h>

#include "framework/any_output.hpp"
#include "framework/executor_access.hpp"
#include "framework/run_members.hpp"
#include "framework/topic_types.hpp"
#include "python_errors.hpp"
#include "python_member.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace gdnav::client::embed {

namespace {

// One interpreter per process, started by the first in-process member and never finalised (the process ends with
// it). Python installs no signal handlers: SIGINT and SIGTERM stay gdnav's. The starting thread gives the GIL up;
// every call into Python takes it (python::StepCall), from whichever thread the executor runs the member in.
void ensure_interpreter() {
    static std::once_flag once;
    std::call_once(once, [] {
        py::initialize_interpreter(false, 0, nullptr, false);
        PyEval_SaveThread();
    });
}

std::string join(const std::set<std::string>& s) {
    std::string out;
    for (const auto& t : s) out += (out.empty() ? "" : ", ") + t;
    return out.empty() ? "none" : out;
}

// Flushes Python's sys.stdout and sys.stderr (a process of the run may end with _Exit; GIL held).
void flush_python_streams() {
    const py::module_ sys = py::module_::import("sys");
    for (const char* s : {"stdout", "stderr"})
        if (py::hasattr(sys, s) && !sys.attr(s).is_none()) sys.attr(s).attr("flush")();
}

}  // namespace

PythonComponent& Host::comp() const {
    if (!comp_) throw std::runtime_error("this member's run is over");
    return *comp_;
}

std::shared_ptr<Port> Host::input(const std::string& topic, framework::Lag lag) {
    PythonComponent& c = comp();
    if (!c.declaring_) throw std::logic_error("Member.input(): declare ports in the class's constructor");
    auto in = std::make_unique<framework::InputBase>(c, topic, lag, framework::require_topic(topic));
    auto port = std::make_shared<Port>(*in, c.state_);
    c.inputs_.push_back(std::move(in));
    return port;
}

std::shared_ptr<Port> Host::output(const std::string& topic) {
    PythonComponent& c = comp();
    if (!c.declaring_) throw std::logic_error("Member.output(): declare ports in the class's constructor");
    auto out = std::make_unique<framework::AnyOutput>(c, topic, framework::require_topic(topic));
    auto port = std::make_shared<Port>(*out);
    c.outputs_.push_back(std::move(out));
    return port;
}

void Host::publish_status(const std::string& message) { framework::ExecutorAccess::publish_status(comp(), message); }
const std::string& Host::name() const { return comp().name(); }
std::uint64_t Host::run_id() const { return comp().run_.run_index; }
StepView Host::step_view() const { return comp().view_; }
const StepCost& Host::cost() const { return comp().cost_; }

PythonComponent::PythonComponent(std::string name, const framework::ComponentRegistry& reg)
    : Component(std::move(name)), reg_(reg) {}

PythonComponent::~PythonComponent() {
    if (!Py_IsInitialized() || !host_) return;
    py::gil_scoped_acquire gil;
    host_->close();
    step_ = py::function();
    finish_ = py::object();
    obj_ = py::object();
    module_ = py::object();
    if (!module_name_.empty()) py::module_::import("sys").attr("modules").attr("pop")(module_name_, py::none());
    host_.reset();
}

void PythonComponent::fail(const std::string& what, const std::string& where) const {
    throw config::ConfigError("config error: " + (where.empty() ? file_ : where) + ": " + what + " (python member '" +
                              name() + "', class " + class_ + ")");
}

void PythonComponent::configure(const config::Config& cfg, const framework::RunInfo& run, rnd::Stream&) {
    file_ = cfg.get_string("file");
    class_ = cfg.get_string("class");
    const std::string replaces = cfg.get_string("replaces", "");
    // Written by the launcher into run.yaml as the record of which file flew; not checked here (the file is read
    // once, at this configure, in each process that hosts the member).
    (void)cfg.get_string("sha256", "");
    run_ = run;
    view_.dt_s = run.dt_s;
    if (!fs::is_regular_file(file_)) fail("no such file");
    framework::register_gdnav_topics();
    ensure_interpreter();
    {
        py::gil_scoped_acquire gil;
        try {
            instantiate();
        } catch (const config::ConfigError&) {
            throw;
        } catch (py::error_already_set& e) {
            const PyErrorText t = describe_error(e, file_);
            fail(t.what, t.where);
        } catch (const std::exception& e) {  // raised by the bindings, e.g. pybind11::type_error
            fail(e.what());
        }
        flush_python_streams();
    }
    check_ports(replaces);
}

void PythonComponent::instantiate() {
    static int loaded = 0;  // each member gets a module of its own (its own globals), even from the same file
    module_name_ = "gdnav_member_" + name() + "_" + std::to_string(++loaded);
    py::module_::import("gdnav_client");  // registers Host with pybind11, whether the file imports it or not
    const py::module_ sys = py::module_::import("sys");
    const py::str dir(fs::path(file_).parent_path().string());
    if (!sys.attr("path").contains(dir)) sys.attr("path").attr("insert")(0, dir);  // its own imports, as a script's
    const py::module_ util = py::module_::import("importlib.util");
    const py::object spec = util.attr("spec_from_file_location")(module_name_, file_);
    if (spec.is_none()) fail("not a Python source file (.py)");
    module_ = util.attr("module_from_spec")(spec);
    sys.attr("modules")[py::str(module_name_)] = module_;
    spec.attr("loader").attr("exec_module")(module_);
    if (!py::hasattr(module_, class_.c_str())) {
        std::set<std::string> classes;
        for (const auto& [k, v] : module_.attr("__dict__").cast<py::dict>())
            if (py::isinstance<py::type>(v) && py::str(v.attr("__module__")).cast<std::string>() == module_name_)
                classes.insert(k.cast<std::string>());
        fail("no class '" + class_ + "' (classes defined there: " + join(classes) + ")");
    }
    const py::object cls = module_.attr(class_.c_str());
    if (!py::isinstance<py::type>(cls)) fail("'" + class_ + "' is not a class");
    host_ = std::make_shared<Host>(*this);
    declaring_ = true;
    try {
        obj_ = cls(host_);
    } catch (...) {
        declaring_ = false;
        throw;
    }
    declaring_ = false;
    const python::ClassCallbacks cb = python::class_callbacks(obj_);
    step_ = cb.step;
    finish_ = cb.finish;
}

// The outputs of the member it replaces are read by the run's other members: the class must produce exactly those.
void PythonComponent::check_ports(const std::string& replaces) const {
    if (replaces.empty() || !reg_.has(replaces)) return;
    const auto original = reg_.create(replaces, name());
    std::set<std::string> want, have;
    for (const framework::OutputBase* o : original->outputs()) want.insert(o->topic());
    for (const framework::OutputBase* o : outputs()) have.insert(o->topic());
    if (want == have) return;
    fail("the class's outputs (" + join(have) + ") are not those of the member it replaces ('" + name() + "', type " +
         replaces + ": " + join(want) + ")");
}

void PythonComponent::step(const framework::StepContext& ctx) {
    std::string failure;
    {
        python::StepCall call(cost_);
        view_ = StepView{ctx.dt_s, ctx.last};
        state_->in_step = true;
        try {
            step_(ctx.k, ctx.t_s);
        } catch (py::error_already_set& e) {
            spdlog::error("[{}] {}", name(), format_traceback(e));
            const PyErrorText t = describe_error(e, file_);
            failure = "Python exception in the step callback: " + t.what + " (" + t.where + ")";
        }
        state_->in_step = false;
    }
    if (!failure.empty()) throw std::runtime_error(failure);
}

void PythonComponent::finish(bool completed) {
    py::gil_scoped_acquire gil;
    if (finish_ && !finish_.is_none()) {
        try {
            finish_(completed);
        } catch (py::error_already_set& e) {
            spdlog::error("[{}] Python exception in finish(): {}", name(), format_traceback(e));
        }
    }
    flush_python_streams();
    spdlog::info("member '{}': Python step callback (in process), {}", name(), cost_.text());
}

}  // namespace gdnav::client::embed
