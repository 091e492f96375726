#pragma once
// Field tables of the IDL message types (Python bindings, fault injection): generated at build time from
// idl/gdnav.idl by gen_fields.py (one table per struct; nested structs are flattened to dotted names such as "stamp.t_s").
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "framework/compat.hpp"

namespace gdnav::framework::fields {

enum class Kind : std::uint8_t { F64, Bool, U8, U32, U64, Enum, String };

struct Field {
    const char* name;                                  // "h_m", "stamp.t_s"
    Kind kind;
    std::size_t count;                                 // array length (1 for scalars); the bound N of a string<N>
    void* (*ptr)(void* msg);                           // first element (all kinds but String)
    std::string (*get_str)(const void* msg);           // String only
    void (*set_str)(void* msg, const std::string& s);  // String only (the caller checks the bound)
    const char* enum_values;                           // Enum only: "A,B,C" (value i = i-th name)
};

struct TypeFields {
    const char* type_name;  // C++ name, as MessageOps::type_name ("gdnav::msg::ImuSample")
    const Field* fields;
    std::size_t count;
};

// The table of a type; nullptr when the generator skipped it (a member the bindings do not support).
const TypeFields* find_type_fields(std::string_view type_name);

}  // namespace gdnav::framework::fields
