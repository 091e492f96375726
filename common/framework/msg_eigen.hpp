#pragma once
// The one conversion between IDL arrays (double[3], quaternions as double[4] w, x, y, z) and the rotation
// toolkit's Eigen types, used by every component wrapper.
#include <array>

#include "framework/compat.hpp"
#include "math/rotation.hpp"

namespace gdnav::framework {

inline math::Vec3 to_vec3(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }
inline std::array<double, 3> to_array(const math::Vec3& v) { return {v.x(), v.y(), v.z()}; }
inline math::Quat to_quat(const std::array<double, 4>& q) { return {q[0], q[1], q[2], q[3]}; }
inline std::array<double, 4> to_array(const math::Quat& q) { return {q.w(), q.x(), q.y(), q.z()}; }

}  // namespace gdnav::framework
