// Stepping the local members, publishing their outputs, StepDone (part of DdsHost::Impl).
#include "dds/host/host_impl.hpp"

#include <spdlog/spdlog.h>

#include "files/write_error.hpp"
#include "framework/executor_access.hpp"

namespace gdnav::dds {

bool DdsHost::Impl::advance() {
    if (!step_error.empty()) return false;  // leaving the run
    bool any = false;
    const host::RunPhase& run = control.run();
    const host::RunTiming& t = run.timing();
    for (auto& l : locals) {
        if (l.index == UINT32_MAX) continue;
        while (!l.awaiting_rejoin && run.may_step(l.next_step)) {
            const std::uint64_t k = l.next_step;
            if (!faults.empty() && !faults.apply(l, k, owned, control)) {
                any = true;
                continue;
            }
            for (host::Channel* ch : l.inputs)
                if (ch->take_fresh()) inputs.read(l, *ch, t.ri);
            if (l.next_step != k) continue;  // an observer that fell behind jumped ahead
            if (!inputs.ready(l, k)) {
                if (!l.observer || !host::step_missed(l, k)) break;
                ++l.skipped;  // an observer never waits for a lost sample
                ++l.next_step;
                any = true;
                continue;
            }
            inputs.record_lateness(l, k);
            step(l, k);
            if (!step_error.empty()) return false;
            ++l.next_step;
            if (l.barrier && ((k + 1) % t.done_every == 0 || k + 1 == t.ri.steps)) control.send_done(l, k);
            any = true;
        }
    }
    return any;
}

void DdsHost::Impl::step(host::Local& l, std::uint64_t k) {
    const framework::RunInfo& ri = control.run().timing().ri;
    const framework::StepContext ctx{k, ri.time_of(k), ri.dt_s, k + 1 == ri.steps};
    try {
        l.comp->step(ctx);
    } catch (const std::exception& e) {
        // Not into the caller (it may be a Fast DDS listener thread): the main loop ends the run for this process.
        step_write_failed = dynamic_cast<const files::WriteError*>(&e) != nullptr;
        std::string what = e.what();
        what = what.substr(0, what.find('\n'));  // one line (a Python error carries its traceback)
        step_error = fmt::format("member '{}' failed at step {} (t = {:.2f} s): {}", l.comp->name(), k, ctx.t_s, what)
                         .substr(0, 1000);  // ComponentStatus.message holds 1024 characters
        return;
    }
    for (auto& o : l.outputs) {
        o.port->ops().set_stamp(o.port->data(), ri.run_index, k, ctx.t_s);
        publish(o, k);
    }
    // A mode change goes to the clock, which logs it for the run: here only at debug level, so that each event is
    // logged once.
    for (const auto& m : framework::ExecutorAccess::take_status(*l.comp)) {
        spdlog::debug("[{}] step {} t={:.2f} s: {}", l.comp->name(), k, ctx.t_s, m);
        control.send_status(l, msg::STATUS_MODE, m);
    }
}

void DdsHost::Impl::publish(host::Output& o, std::uint64_t k) {
    for (const auto& r : o.routes)
        if (!host::hand_over(r, locals[r.consumer], o.port->data(), k))
            host::Inputs::warn_too_far(locals[r.consumer], *r.channel, k);
    if (o.routes.empty() || host::read_outside(o)) o.writer->write(o.port->data());
    if (host::mirror_due(o, k)) o.mirror->write(o.port->data());
}

}  // namespace gdnav::dds
