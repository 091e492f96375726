#pragma once
// The number keys of a configuration section that fill the fields of one struct, as a table: one list serves reading
// the section (in table order, so the first bad key is the one reported) and writing it back (a drawn scenario).
#include <array>
#include <cstddef>

#include "config/config.hpp"

namespace gdnav::core::config {

template <class P>
struct NumberKey {
    const char* key;
    double P::*field;
    bool degrees;                   // the file holds degrees, the field radians
    Range range;                    // in the file's unit
    double P::*at_least{nullptr};   // when set, the range starts at this field's value (a key earlier in the table)
};

template <class P, std::size_t N>
P read_number_keys(const Config& c, const std::array<NumberKey<P>, N>& keys) {
    P p;
    for (const NumberKey<P>& k : keys) {
        const Range r{k.at_least ? p.*k.at_least : k.range.lo, k.range.hi};
        p.*k.field = k.degrees ? c.get_angle_deg(k.key, r) : c.get_double(k.key, r);
    }
    return p;
}

}  // namespace gdnav::core::config
namespace gdnav { namespace config = core::config; }  // the short name (docs/architecture.md, "Namespaces")
