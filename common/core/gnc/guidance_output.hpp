#pragma once
// What guidance commands every step: the content of the IDL topic GuidanceTargets. Guidance writes it, control reads
// it; it lives here so that neither model includes the other.
#include <cstdint>

#include "gnc/modes.hpp"

namespace gdnav::core::gnc {

struct GuidanceOutput {
    std::uint32_t operation{0};   // index of the mission operation being flown
    ChannelTargets targets;       // mode and SI target of each control channel
    bool finished{false};         // the mission's last operation is done
};

}  // namespace gdnav::core::gnc
namespace gdnav { namespace gnc = core::gnc; }  // the short name (docs/architecture.md, "Namespaces")

namespace gdnav::guidance {
using GuidanceOutput = gnc::GuidanceOutput;  // its name in the guidance model's API
}
