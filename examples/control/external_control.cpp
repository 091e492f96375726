// An external `control` member written as a user would: the paper's autopilot from gdnav's public control library
// (gdnav::control_model), joined to a run through gdnav::client. Start the run with `--external control`:
//
//   gdnav run --scenario paper2 --layout distributed --external control --domain 7 --out out/ext
//   gdnav-example-control --domain 7 [--x-autopilot FILE]
//
// It reads the same inputs as the built-in member (components/control/control_component.cpp), calls the same
// library with the same configuration and compiler rules (-ffp-contract=off), so its ControlCommands are
// bit-identical to the built-in run's. Run it with --free-running for real-time hardware-in-the-loop runs.
#include <cstdio>
#include <exception>

#include <gdnav/client/member.hpp>

#include "control/model/autopilot.hpp"
#include "gnc/modes.hpp"
#include "framework/msg_eigen.hpp"
#include "framework/run_config.hpp"

namespace gc = gdnav::client;
namespace msg = gdnav::msg;

int main(int argc, char** argv) try {
    std::vector<std::string> extra;
    gc::Options opt = gc::Options::from_args(argc, argv, "control", &extra);
    std::string autopilot_file = (gdnav::runtime::config_dir() / "control/mugin_autopilot.yaml").string();
    for (std::size_t i = 0; i + 1 < extra.size(); i += 2)
        if (extra[i] == "--x-autopilot") autopilot_file = extra[i + 1];

    gc::Member m(opt);
    const auto& air = m.input<msg::AirDataEstimate>("gdnav/AirDataEstimate");
    const auto& att = m.input<msg::AttitudeEstimate>("gdnav/AttitudeEstimate");
    const auto& pos = m.input<msg::PositionEstimate>("gdnav/PositionEstimate");
    const auto& targets = m.input<msg::GuidanceTargets>("gdnav/GuidanceTargets");
    auto& out = m.output<msg::ControlCommands>("gdnav/ControlCommands");

    gdnav::control::Autopilot autopilot;
    autopilot.configure(gdnav::config::Config::load(autopilot_file));  // ConfigError names file and key
    bool initialized = false;

    m.on_step([&](const gc::StepInfo& s) {
        if (!air.available() || !att.available() || !pos.available() || !targets.available()) return;  // hold
        gdnav::control::ControlEstimates e;
        e.airspeed_mps = air.get().tas_mps();
        e.aoa_rad = air.get().aoa_rad();
        e.aos_rad = air.get().aos_rad();
        e.q_nb = gdnav::runtime::to_quat(att.get().q_nb());
        e.v_n_mps = gdnav::runtime::to_vec3(pos.get().v_n_mps());
        e.pressure_altitude_m = air.get().Hp_m();
        e.altitude_m = pos.get().h_m();
        if (!initialized) {
            autopilot.initialize(e);
            initialized = true;
        }
        namespace gnc = gdnav::gnc;
        const auto& t = targets.get();
        gdnav::guidance::GuidanceOutput g;
        g.operation = t.operation();
        g.finished = t.finished();
        g.targets.throttle_mode = gnc::mode_from_octet<gnc::ThrottleMode>(t.throttle_mode()).value_or(gnc::ThrottleMode::airspeed);
        g.targets.throttle_target = t.throttle_target();
        g.targets.elevator_mode = gnc::mode_from_octet<gnc::ElevatorMode>(t.elevator_mode()).value_or(gnc::ElevatorMode::pitch);
        g.targets.elevator_target = t.elevator_target();
        g.targets.aileron_mode = gnc::mode_from_octet<gnc::AileronMode>(t.aileron_mode()).value_or(gnc::AileronMode::bank);
        g.targets.aileron_target = t.aileron_target();
        g.targets.rudder_mode = gnc::mode_from_octet<gnc::RudderMode>(t.rudder_mode()).value_or(gnc::RudderMode::sideslip);
        g.targets.rudder_target = t.rudder_target();
        const gdnav::control::ControlOutput u = autopilot.step(s.k, g, e);
        out.value().throttle(u.throttle);
        out.value().elevator_rad(u.elevator_rad);
        out.value().aileron_rad(u.aileron_rad);
        out.value().rudder_rad(u.rudder_rad);
    });
    return m.run();
} catch (const std::exception& e) {
    std::fprintf(stderr, "gdnav-example-control: %s\n", e.what());
    return 2;
}
