#pragma once
// gdnav::runtime, kept for existing external members (framework/compat.hpp): it names everything of gdnav::dds too.
#include "framework/compat.hpp"

namespace gdnav::dds {}

namespace gdnav::runtime {
using namespace ::gdnav::dds;
}  // namespace gdnav::runtime
