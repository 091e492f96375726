#pragma once
// A port of a Python member: field access by name on the sample an input is bound to, or on an output's value.
#include <memory>
#include <string>
#include <unordered_map>

#include <pybind11/pybind11.h>

#include "framework/fields/field_table.hpp"
#include "framework/component.hpp"

namespace gdnav::client::python {

using framework::fields::Field;
using framework::fields::Kind;
using framework::fields::TypeFields;
using framework::fields::find_type_fields;

// Shared by a member and its ports: inputs are readable only while the step callback runs (the host rebinds and
// frees their samples between steps).
struct StepState {
    bool in_step{false};
};

class Port {
public:
    Port(const framework::InputBase& in, std::shared_ptr<const StepState> state);
    explicit Port(framework::OutputBase& out);

    [[nodiscard]] const std::string& topic() const { return topic_; }
    [[nodiscard]] bool is_output() const { return out_ != nullptr; }
    [[nodiscard]] bool available() const;
    [[nodiscard]] bool lost() const;
    [[nodiscard]] pybind11::object get(const std::string& field) const;
    void set(const std::string& field, const pybind11::handle& value);
    [[nodiscard]] pybind11::dict as_dict() const;
    void update(const pybind11::dict& values);
    [[nodiscard]] pybind11::list fields() const;  // [(name, "double[3]"), ...]
    [[nodiscard]] std::string describe() const;

private:
    Port(std::string topic, const char* type_name);
    [[nodiscard]] const Field& field(const std::string& name) const;
    [[nodiscard]] void* sample() const;  // throws when an input has no sample now
    [[nodiscard]] pybind11::object read(const Field& f) const;

    std::string topic_;
    const TypeFields* table_;
    std::unordered_map<std::string, const Field*> by_name_;
    const framework::InputBase* in_{nullptr};
    framework::OutputBase* out_{nullptr};
    std::shared_ptr<const StepState> state_;
};

// "double[3]", "unsigned long", "string<64>", "enum {A, B}".
std::string type_text(const Field& f);

}  // namespace gdnav::client::python
