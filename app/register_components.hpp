#pragma once
#include "framework/registry.hpp"

namespace gdnav::cli {
// Registers every production component linked into gdnav.
void register_all_components(framework::ComponentRegistry& reg);
}  // namespace gdnav::cli
