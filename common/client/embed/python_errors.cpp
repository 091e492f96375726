#include "python_errors.hpp"

namespace py = pybind11;

namespace gdnav::client::embed {

namespace {

std::string first_line(const std::string& s) { return s.substr(0, s.find('\n')); }

}  // namespace

PyErrorText describe_error(py::error_already_set& e, const std::string& file) {
    const py::object& type = e.type();
    const py::object& value = e.value();
    PyErrorText t{file, py::str(type.attr("__name__"))};
    long line = -1;
    std::string message;
    if (PyErr_GivenExceptionMatches(type.ptr(), PyExc_SyntaxError)) {
        message = py::str(value.attr("msg"));
        if (!value.attr("filename").is_none()) t.where = py::str(value.attr("filename"));
        if (!value.attr("lineno").is_none()) line = value.attr("lineno").cast<long>();
    } else {
        message = py::str(value);
        if (e.trace()) {
            const py::list frames = py::module_::import("traceback").attr("extract_tb")(e.trace());
            for (const auto& f : frames)
                if (py::str(f.attr("filename")).cast<std::string>() == file) line = f.attr("lineno").cast<long>();
        }
    }
    if (line > 0) t.where += ":" + std::to_string(line);
    message = first_line(message);
    if (!message.empty()) t.what += ": " + message;
    return t;
}

std::string format_traceback(py::error_already_set& e) {
    const py::list lines =
        py::module_::import("traceback").attr("format_exception")(e.type(), e.value(), e.trace());
    std::string s;
    for (const auto& l : lines) s += py::str(l).cast<std::string>();
    while (!s.empty() && s.back() == '\n') s.pop_back();
    return s;
}

}  // namespace gdnav::client::embed
