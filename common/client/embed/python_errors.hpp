#pragma once
// Python exceptions as one line that names where they came from (docs/python.md, "In-process members").
#include <string>

#include <pybind11/pybind11.h>

namespace gdnav::client::embed {

struct PyErrorText {
    std::string where;  // "FILE:LINE" (LINE of the innermost frame in `file`; a SyntaxError's own file and line)
    std::string what;   // "Type: first line of the message"
};

// GIL held.
PyErrorText describe_error(pybind11::error_already_set& e, const std::string& file);
// The exception's traceback as Python prints it (GIL held).
std::string format_traceback(pybind11::error_already_set& e);

}  // namespace gdnav::client::embed
