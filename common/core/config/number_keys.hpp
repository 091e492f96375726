#pragma once
// The number keys of a configuration section that fill the fields of one struct, as a table: one list serves reading
// the section (in table order, so the first bad key is the one reported) and writing it back (a drawn scenario).
#include <array>
#include <cstddef>
#include <cstdint>
#include <numbers>

#include "config/config.hpp"

namespace gdnav::core::config {

template <class P>
struct NumberKey {
    const char* key;
    double P::*field;
    bool degrees;                   // the file holds degrees, the field radians
    Range range;                    // in the file's unit
    double P::*at_least{nullptr};   // when set, the range starts at this field's value (a key earlier in the table)
    int P::*count{nullptr};         // instead of `field`: a whole number (the range's bounds as integers)
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

// The same table with every key optional: a key not given keeps its value in `base` (a section that adds to
// settings made elsewhere). Degrees convert as math::deg2rad / rad2deg do (the same constant, without Eigen).
template <class P, std::size_t N>
P read_number_keys(const Config& c, const std::array<NumberKey<P>, N>& keys, P base) {
    constexpr double kDeg = std::numbers::pi / 180.0;
    for (const NumberKey<P>& k : keys) {
        if (k.count) {
            const auto lo = static_cast<std::int64_t>(k.range.lo), hi = static_cast<std::int64_t>(k.range.hi);
            base.*k.count = static_cast<int>(c.get_int(k.key, base.*k.count, lo, hi));
        } else if (k.degrees) {
            base.*k.field = c.get_double(k.key, base.*k.field / kDeg, k.range) * kDeg;
        } else {
            base.*k.field = c.get_double(k.key, base.*k.field, k.range);
        }
    }
    return base;
}

}  // namespace gdnav::core::config
namespace gdnav { namespace config = core::config; }  // the short name (docs/architecture.md, "Namespaces")
