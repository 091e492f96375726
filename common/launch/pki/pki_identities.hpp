#pragma once
// The identities `gdnav pki init` makes for a run: the clock (Tick, RunControl, ComponentStatus), `operator`
// (FaultRequest, for gdnav fault), every configured member of the run (its output topics, StepDone,
// ComponentStatus), `recorder` (added by gdnav run --record), `composed` (every member's outputs: the process of the
// composed layout) and each external member given as NAME=TOPIC[,TOPIC...].
#include <string>
#include <vector>

#include "framework/registry.hpp"
#include "framework/run_config.hpp"
#include "launch/pki/pki.hpp"

namespace gdnav::launch::pki {

// Throws config::ConfigError (one line naming the --member value) for a malformed external member or a name that
// already has an identity.
std::vector<Identity> run_identities(const framework::RunConfig& rc, const framework::ComponentRegistry& reg,
                                     const std::vector<std::string>& external_members);

}  // namespace gdnav::launch::pki
