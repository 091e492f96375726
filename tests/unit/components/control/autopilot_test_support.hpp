#pragma once
// What the autopilot tests share: the autopilot with the reference gains of config/control and guidance targets
// built from their five fields.
#include "control/model/autopilot.hpp"

namespace gdnav::control::test {

inline const char* kAutopilotFile = GDNAV_CONFIG_DIR "/control/mugin_autopilot.yaml";

inline Autopilot make_autopilot() {
    Autopilot ap;
    ap.configure(config::Config::load(kAutopilotFile));
    return ap;
}

inline guidance::GuidanceOutput targets(double v, gnc::ElevatorMode em, double e, gnc::AileronMode am, double a) {
    guidance::GuidanceOutput g;
    g.targets.throttle_target = v;
    g.targets.elevator_mode = em;
    g.targets.elevator_target = e;
    g.targets.aileron_mode = am;
    g.targets.aileron_target = a;
    return g;
}

}  // namespace gdnav::control::test
