#include "register_components.hpp"

#include "control_component.hpp"
#include "flight_physics_component.hpp"
#include "guidance_component.hpp"
#include "live_bridge.hpp"
#include "nav_recorder.hpp"
#include "paper_scenarios.hpp"
#include "nav_components.hpp"
#include "recorder.hpp"
#include "replay.hpp"
#include "sensor_components.hpp"
#include "truth_as_estimate.hpp"
#ifdef GDNAV_PYTHON_EMBED
#include "client/embed/python_member.hpp"
#endif

namespace gdnav::cli {

void register_all_components(framework::ComponentRegistry& reg) {
    gdnav::recorder::register_recorder(reg);
    replay::register_replay(reg);
    live::register_live(reg);
    physics::register_flight_physics(reg);
    sensors::register_sensor_components(reg);
    nav::register_nav_components(reg);
    guidance::register_guidance_component(reg);
    control::register_control_component(reg);
    diagnostics::register_diagnostics(reg);
    nav_recorder::register_nav_recorder(reg);
    scenario::register_paper_scenarios();
#ifdef GDNAV_PYTHON_EMBED
    client::embed::register_python_member(reg);  // run.members: {NAME: {python: ...}} (docs/python.md)
#endif
}

}  // namespace gdnav::cli
