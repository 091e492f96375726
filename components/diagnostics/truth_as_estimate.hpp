#pragma once
// truth_as_estimate (diagnostic): republishes Truth(k) as the three navigation estimate topics, so guidance and
// control can be closed on perfect navigation (tests of the flight physics and autopilot, and a reference
// against which the real filters are judged). Never part of a default run once navigation exists.
#include "framework/registry.hpp"

namespace gdnav::diagnostics {
void register_diagnostics(framework::ComponentRegistry& reg);
}
