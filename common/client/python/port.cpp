#include "port.hpp"

#include <cstring>
#include <limits>
#include <stdexcept>

#include <pybind11/numpy.h>

namespace py = pybind11;

namespace gdnav::client::python {

namespace {

const char* kind_text(Kind k) {
    switch (k) {
        case Kind::F64: return "double";
        case Kind::Bool: return "boolean";
        case Kind::U8: return "octet";
        case Kind::U32: return "unsigned long";
        case Kind::U64: return "unsigned long long";
        case Kind::Enum: return "enum";
        case Kind::String: return "string";
    }
    return "?";
}

template <class T>
py::object read_number(const void* p, std::size_t n) {
    if (n == 1) {
        T v;
        std::memcpy(&v, p, sizeof v);
        if constexpr (std::is_same_v<T, double>) return py::float_(v);
        else if constexpr (std::is_same_v<T, bool>) return py::bool_(v);
        else return py::int_(v);
    }
    py::array_t<T> a(static_cast<py::ssize_t>(n));  // a copy: the sample is gone after the step
    std::memcpy(a.mutable_data(), p, n * sizeof(T));
    return a;
}

std::size_t enum_count(const Field& f) {
    std::size_t n = 1;
    for (const char* c = f.enum_values; *c; ++c) n += *c == ',';
    return n;
}

}  // namespace

std::string type_text(const Field& f) {
    if (f.kind == Kind::String) return "string<" + std::to_string(f.count) + ">";
    if (f.kind == Kind::Enum) return std::string("enum {") + f.enum_values + "}";
    return std::string(kind_text(f.kind)) + (f.count > 1 ? "[" + std::to_string(f.count) + "]" : "");
}

Port::Port(std::string topic, const char* type_name) : topic_(std::move(topic)), table_(find_type_fields(type_name)) {
    if (!table_)
        throw std::invalid_argument("topic '" + topic_ + "' (" + type_name +
                                    ") has members the Python bindings do not support");
    for (std::size_t i = 0; i < table_->count; ++i) by_name_.emplace(table_->fields[i].name, &table_->fields[i]);
}

Port::Port(const framework::InputBase& in, std::shared_ptr<const StepState> state)
    : Port(in.topic(), in.ops().type_name) {
    in_ = &in;
    state_ = std::move(state);
}

Port::Port(framework::OutputBase& out) : Port(out.topic(), out.ops().type_name) { out_ = &out; }

bool Port::available() const { return out_ || (state_->in_step && in_->available()); }

bool Port::lost() const { return in_ && in_->lost(); }

std::string Port::describe() const {
    std::string s = "fields of " + topic_ + ":";
    for (std::size_t i = 0; i < table_->count; ++i)
        s += std::string(i ? ", " : " ") + table_->fields[i].name + " (" + type_text(table_->fields[i]) + ")";
    return s;
}

const Field& Port::field(const std::string& name) const {
    const auto it = by_name_.find(name);
    if (it == by_name_.end()) throw py::key_error(topic_ + " has no field '" + name + "'; " + describe());
    return *it->second;
}

void* Port::sample() const {
    if (out_) return out_->data();
    if (!state_->in_step)
        throw std::runtime_error("input " + topic_ + " can be read only inside the step callback");
    if (!in_->available())
        throw std::runtime_error("input " + topic_ + (in_->lost() ? " was lost (its producer was declared dead)"
                                                                  : " has no sample at this step") +
                                 "; test available() first");
    // Inputs are handed out read-only (copies); the accessors are shared with outputs and take a mutable pointer.
    return const_cast<void*>(in_->data_ptr());
}

py::object Port::read(const Field& f) const {
    void* m = sample();
    if (f.kind == Kind::String) return py::str(f.get_str(m));
    const void* p = f.ptr(m);
    switch (f.kind) {
        case Kind::F64: return read_number<double>(p, f.count);
        case Kind::Bool: return read_number<bool>(p, f.count);
        case Kind::U8: return read_number<std::uint8_t>(p, f.count);
        case Kind::U32:
        case Kind::Enum: return read_number<std::uint32_t>(p, f.count);  // enums are 32-bit (fastddsgen)
        case Kind::U64: return read_number<std::uint64_t>(p, f.count);
        case Kind::String: break;
    }
    throw std::logic_error("unreachable");
}

py::object Port::get(const std::string& name) const { return read(field(name)); }

py::dict Port::as_dict() const {
    py::dict d;
    for (std::size_t i = 0; i < table_->count; ++i) d[table_->fields[i].name] = read(table_->fields[i]);
    return d;
}

py::list Port::fields() const {
    py::list l;
    for (std::size_t i = 0; i < table_->count; ++i)
        l.append(py::make_tuple(table_->fields[i].name, type_text(table_->fields[i])));
    return l;
}

void Port::set(const std::string& name, const py::handle& value) {
    if (!out_) throw std::runtime_error("input " + topic_ + " is read-only; assign fields of outputs");
    const Field& f = field(name);
    // Built only for an error message: set() runs for every field a Python member writes, every step.
    const auto what = [&] { return "field '" + name + "' of " + topic_ + " (" + type_text(f) + ")"; };
    if (name.rfind("stamp.", 0) == 0) throw std::invalid_argument(what() + " is set by the host when it publishes");
    void* m = out_->data();
    if (f.kind == Kind::String) {
        if (!py::isinstance<py::str>(value)) throw py::type_error(what() + ": expected a str");
        const auto s = value.cast<std::string>();
        if (s.size() > f.count)
            throw std::invalid_argument(what() + ": " + std::to_string(s.size()) + " characters, at most " +
                                        std::to_string(f.count));
        f.set_str(m, s);
        return;
    }
    void* p = f.ptr(m);
    if (f.kind == Kind::F64 && f.count > 1) {
        auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
        if (!a) {
            PyErr_Clear();
            throw py::type_error(what() + ": expected an array of " + std::to_string(f.count) + " numbers");
        }
        if (a.ndim() != 1 || static_cast<std::size_t>(a.size()) != f.count) {
            std::string shape;
            for (py::ssize_t i = 0; i < a.ndim(); ++i) shape += (i ? ", " : "") + std::to_string(a.shape(i));
            throw std::invalid_argument(what() + ": expected " + std::to_string(f.count) + " values, got shape (" +
                                        shape + (a.ndim() == 1 ? ",)" : ")"));
        }
        std::memcpy(p, a.data(), f.count * sizeof(double));
        return;
    }
    if (f.count > 1) throw std::invalid_argument(what() + ": assigning arrays of this kind is not supported");
    try {
        switch (f.kind) {
            case Kind::F64: {
                if (py::isinstance<py::str>(value)) throw py::cast_error();
                const double v = value.cast<double>();
                std::memcpy(p, &v, sizeof v);
                return;
            }
            case Kind::Bool: {
                const bool v = value.cast<bool>();
                std::memcpy(p, &v, sizeof v);
                return;
            }
            case Kind::U8:
            case Kind::U32:
            case Kind::Enum:
            case Kind::U64: {
                if (py::isinstance<py::float_>(value) || py::isinstance<py::bool_>(value)) throw py::cast_error();
                const long long v = value.cast<long long>();
                const unsigned long long hi = f.kind == Kind::U8     ? 255ULL
                                              : f.kind == Kind::U32  ? 0xFFFFFFFFULL
                                              : f.kind == Kind::Enum ? enum_count(f) - 1
                                                                     : std::numeric_limits<unsigned long long>::max();
                if (v < 0 || static_cast<unsigned long long>(v) > hi)
                    throw std::invalid_argument(what() + ": " + std::to_string(v) + " out of range [0, " +
                                                std::to_string(hi) + "]");
                const auto u = static_cast<std::uint64_t>(v);
                if (f.kind == Kind::U8) *static_cast<std::uint8_t*>(p) = static_cast<std::uint8_t>(u);
                else if (f.kind == Kind::U64) std::memcpy(p, &u, sizeof u);
                else {
                    const auto u32 = static_cast<std::uint32_t>(u);
                    std::memcpy(p, &u32, sizeof u32);
                }
                return;
            }
            case Kind::String: break;
        }
    } catch (const py::cast_error&) {
        throw py::type_error(what() + ": cannot assign a value of type " +
                             py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>());
    }
}

void Port::update(const py::dict& values) {
    for (const auto& [k, v] : values) {
        if (!py::isinstance<py::str>(k)) throw py::type_error(topic_ + ": field names must be str");
        set(k.cast<std::string>(), v);
    }
}

}  // namespace gdnav::client::python
