// Inputs by step, stepping the local members, publishing and StepDone (part of DdsHost::Impl).
#include "dds/host/host_impl.hpp"

#include <algorithm>

#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <spdlog/spdlog.h>

namespace gdnav::runtime {

using namespace eprosima::fastdds::dds;

void DdsHost::Impl::read_data(Local& l, Channel& ch) {
    if (ch.reader == nullptr) return;  // an observer's input before CONFIGURE (make_deferred_readers)
    SampleInfo info;
    while (ch.reader->take_next_sample(ch.scratch, &info) == ReturnCode_t::RETCODE_OK) {
        if (!info.valid_data || ch.ops->run_of(ch.scratch) != ri.run_index) continue;
        if (ch.free) {
            ch.ops->copy(ch.latest, ch.scratch);
            ch.has_latest = true;
            continue;
        }
        const std::uint64_t s = ch.ops->step_of(ch.scratch);
        if (l.observer) ch.saw(s);  // only an observer's lost-step test reads it
        long at = host::inbox_index(ch, l.next_step, s);
        if (at == host::kOlder) continue;
        if (at == host::kTooFar && l.observer) {
            // An observer that fell behind (paused, or a slow machine): it gives up the steps before the ones its
            // inbox can hold with this sample, rather than dropping the samples it can still use.
            const auto lag = static_cast<std::uint64_t>(ch.port->lag());
            const std::uint64_t first = s + lag + 1 - kInboxRing;
            l.skipped += first - l.next_step;
            l.next_step = first;
            at = host::inbox_index(ch, l.next_step, s);
        }
        if (at == host::kTooFar) {
            warn_too_far(l, ch, s);
            continue;
        }
        const auto i = static_cast<std::size_t>(at);
        std::swap(ch.slot[i], ch.scratch);
        ch.slot_step[i] = s;
        ch.full[i] = true;
    }
}

void DdsHost::Impl::warn_too_far(const Local& l, const Channel& ch, std::uint64_t s) {
    if (l.killed) return;  // a member killed by a fault does not read its inputs
    spdlog::warn("input '{}': sample of step {} is too far ahead of step {}; dropped", ch.port->topic(), s,
                 l.next_step);
}

// A local member's output of step k: into the inboxes of the local readers, and on DDS if anyone outside reads it.
void DdsHost::Impl::publish(host::Output& o, std::uint64_t k) {
    for (const auto& r : o.routes)
        if (!host::hand_over(r, locals[r.consumer], o.port->data(), k))
            warn_too_far(locals[r.consumer], *r.channel, k);
    if (o.routes.empty() || host::read_outside(o)) o.writer->write(o.port->data());
    if (host::mirror_due(o, k)) o.mirror->write(o.port->data());
}

bool DdsHost::Impl::inputs_ready(const Local& l, std::uint64_t k) {
    for (Channel* ch : l.inputs) {
        if (ch->lost) {
            ch->port->bind(nullptr);
            continue;
        }
        if (ch->free) {
            ch->port->bind(ch->has_latest ? ch->latest : nullptr);
            continue;
        }
        const std::uint64_t lag = static_cast<std::uint64_t>(ch->port->lag());
        if (k < lag) {
            ch->port->bind(nullptr);
            continue;
        }
        const std::uint64_t need = k - lag;
        if (!ch->port->on_stride(need)) {  // not a step it reads: nothing sent, nothing to wait for
            ch->port->bind(nullptr);
            continue;
        }
        if (need < ch->lost_until) {  // its producer was dead then
            ch->port->set_lost(true);
            continue;
        }
        if (ch->revived) ch->port->set_lost(false);
        if (ch->faults && ch->faults->producer_killed(need)) {  // nothing was published: do not wait
            ch->port->set_lost(true);
            continue;
        }
        const std::size_t i = need % kInboxRing;
        if (!ch->full[i] || ch->slot_step[i] != need) return false;
        if (ch->faults) {
            const auto d = ch->faults->apply(need, ch->slot[i]);
            ch->port->set_lost(d.lost);
            ch->port->bind(d.data);
            continue;
        }
        ch->port->bind(ch->slot[i]);
    }
    return true;
}

void DdsHost::Impl::send_done(const Local& l, std::uint64_t k) {
    done.run_id(ri.run_index);
    done.step(k);
    done.member_index(l.index);
    done_writer->write(&done);
}

// Free inputs of a step about to run: how many steps old the sample used is (once per executed step).
void DdsHost::Impl::record_lateness(const Local& l, std::uint64_t k) {
    if (opt.free_running) return;  // a free-running member's own inputs are not a deadline
    for (Channel* ch : l.inputs) {
        if (!ch->free || ch->lost) continue;
        if (!ch->has_latest) {
            ch->lateness.add(-1);
            continue;
        }
        const auto need = static_cast<std::int64_t>(k) - static_cast<std::int64_t>(ch->port->lag());
        const auto have = static_cast<std::int64_t>(ch->ops->step_of(ch->latest));
        ch->lateness.add(std::max<std::int64_t>(need - have, 0));  // a newer sample than needed is on time
    }
}

// Steps every local member that can; returns true if any stepped.
bool DdsHost::Impl::advance() {
    bool any = false;
    for (auto& l : locals) {
        if (l.index == UINT32_MAX) continue;
        while (!l.awaiting_rejoin && have_tick && l.next_step <= tick_step + window_steps &&
               l.next_step < ri.steps) {
            const std::uint64_t k = l.next_step;
            if (!schedule.empty() && !apply_member_faults(l, k)) {
                any = true;
                continue;
            }
            for (Channel* ch : l.inputs) read_data(l, *ch);
            if (l.next_step != k) continue;  // an observer that fell behind jumped ahead
            if (!inputs_ready(l, k)) {
                if (!l.observer || !host::step_missed(l, k)) break;
                ++l.skipped;  // an observer never waits for a lost sample
                ++l.next_step;
                any = true;
                continue;
            }
            record_lateness(l, k);
            const StepContext ctx{k, ri.time_of(k), ri.dt_s, k + 1 == ri.steps};
            l.comp->step(ctx);
            for (auto& o : l.outputs) {
                o.port->ops().set_stamp(o.port->data(), ri.run_index, k, ctx.t_s);
                publish(o, k);
            }
            // A mode change goes to the clock, which logs it for the run: here only at debug level, so that each
            // event is logged once.
            for (auto& m : l.comp->pending_status()) {
                spdlog::debug("[{}] step {} t={:.2f} s: {}", l.comp->name(), k, ctx.t_s, m);
                send_status(l, msg::STATUS_MODE, m);
            }
            l.comp->pending_status().clear();
            ++l.next_step;
            if (in_barrier(l) && ((k + 1) % done_every == 0 || k + 1 == ri.steps)) send_done(l, k);
            any = true;
        }
    }
    return any;
}

void DdsHost::Impl::report_observers() {
    for (const auto& l : locals) {
        if (!l.observer) continue;
        const std::uint64_t computed = l.next_step - l.skipped;
        const std::uint64_t unreached = ri.steps > l.next_step ? ri.steps - l.next_step : 0;  // the run ended first
        const std::string tail = unreached ? fmt::format(", {} not reached before the end", unreached) : "";
        if (l.skipped == 0 && unreached == 0)
            spdlog::info("observer '{}': computed {} of {} steps, none skipped", l.comp->name(), computed, ri.steps);
        else
            spdlog::warn("observer '{}': computed {} of {} steps, skipped {}{} (samples lost on the best-effort "
                         "readers, or it fell behind)", l.comp->name(), computed, ri.steps, l.skipped, tail);
    }
}

// Free-running inputs (hardware-in-the-loop): summary lines and <out>/lateness/<member>.yaml.
void DdsHost::Impl::report_lateness() {
    if (opt.free_running) return;  // a free-running member's own inputs are not a deadline
    for (const auto& l : locals) {
        std::vector<std::pair<std::string, const Lateness*>> inputs;
        for (const Channel* ch : l.inputs)
            if (ch->free) inputs.emplace_back(ch->port->topic(), &ch->lateness);
        runtime::report_lateness(l.comp->name(), inputs, rc.out_dir);
    }
}

}  // namespace gdnav::runtime
