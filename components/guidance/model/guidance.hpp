#pragma once
// Guidance: turns a Mission into control targets, one operation at a time (docs/guidance-control.md, "Guidance").
//
// Input  (every 10-ms step, after navigation):  t_s [s], NavState est (navigation estimates, SI)
// Output (every step):                          GuidanceOutput, the content of IDL topic GuidanceTargets:
//     operation   index of the active operation
//     targets     mode + SI target of the throttle, elevator, aileron and rudder channels (gnc::ChannelTargets)
//     finished    true once the last operation's trigger has fired or t >= mission.t_end_s
//
// Per step: on the first call operation 0 starts (its trigger is armed with this step's estimate). Then the active
// operation's trigger is evaluated on this step's estimate; when it fires the next operation starts at once (armed
// with the same estimate) and is evaluated in turn, so the targets returned are those of the operation active
// after this step's estimate. When the last trigger fires the mission is finished and its last targets are kept.
// Deterministic; no allocation per step.
#include <cstddef>
#include <cstdint>

#include "gnc/guidance_output.hpp"
#include "gnc/mission.hpp"
#include "trigger.hpp"

namespace gdnav::guidance {

class Guidance {
public:
    // Validates the mission (std::invalid_argument when it cannot be flown).
    explicit Guidance(const Mission& mission);

    GuidanceOutput step(double t_s, const NavState& est);

    [[nodiscard]] const Mission& mission() const { return mission_; }
    [[nodiscard]] std::size_t operation() const { return op_; }
    [[nodiscard]] bool finished() const { return finished_; }
    // Time at which the active operation started (valid after the first step).
    [[nodiscard]] double operation_start_s() const { return trigger_.start_time_s(); }

private:
    void start_operation(std::size_t op, double t_s, const NavState& est);

    Mission mission_;
    TriggerState trigger_;
    std::size_t op_{0};
    bool started_{false};
    bool finished_{false};
};

}  // namespace gdnav::guidance
