#pragma once
// gdnav::runtime: the one namespace of the framework and dds layers before each layer had its own
// (docs/architecture.md, "Namespaces"). Kept for existing external members only, which may still name
// gdnav::runtime::to_quat or runtime::Component: it names everything of gdnav::framework (and, with a dds header,
// of gdnav::dds, dds/compat.hpp). Nothing in gdnav uses it (tests/architecture/check_layers.py).
namespace gdnav::framework {}

namespace gdnav::runtime {
using namespace ::gdnav::framework;
}  // namespace gdnav::runtime
