#pragma once
#include "framework/registry.hpp"

namespace gdnav::app {
// Registers every production component linked into gdnav.
void register_all_components(runtime::ComponentRegistry& reg);
}  // namespace gdnav::app
