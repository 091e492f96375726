#include "guidance.hpp"

#include <spdlog/spdlog.h>

namespace gdnav::guidance {

Guidance::Guidance(const Mission& mission) : mission_(mission) { validate(mission_); }

void Guidance::start_operation(std::size_t op, double t_s, const NavState& est) {
    op_ = op;
    trigger_.start(mission_.operations[op_].trigger, t_s, est);
    spdlog::debug("guidance '{}': operation {} starts at t = {:.2f} s (trigger {})", mission_.name, op_, t_s,
                  trigger_name(mission_.operations[op_].trigger.kind));
}

GuidanceOutput Guidance::step(double t_s, const NavState& est) {
    if (!started_) {
        started_ = true;
        start_operation(0, t_s, est);
    }
    if (!finished_) {
        // Each operation can end at most once per step, so this loop is bounded by the number of operations.
        for (std::size_t n = 0; n < mission_.operations.size(); ++n) {
            if (!trigger_.fired(t_s, est)) break;
            if (op_ + 1 == mission_.operations.size()) {
                finished_ = true;
                break;
            }
            start_operation(op_ + 1, t_s, est);
        }
        if (t_s + kTimeTolerance_s >= mission_.t_end_s) finished_ = true;
        if (finished_) spdlog::debug("guidance '{}': mission finished at t = {:.2f} s", mission_.name, t_s);
    }
    GuidanceOutput out;
    out.operation = static_cast<std::uint32_t>(op_);
    out.targets = mission_.operations[op_].targets;
    out.finished = finished_;
    return out;
}

}  // namespace gdnav::guidance
