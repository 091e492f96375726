// The fault schedule in the host: live faults, kills, restarts, rejoin (part of DdsHost::Impl).
#include "dds/host/host_impl.hpp"

#include <algorithm>

#include <spdlog/spdlog.h>

namespace gdnav::runtime {

using namespace eprosima::fastdds::dds;

// The clock's fault schedule (protocol version 2). Returns false when it cannot be read.
bool DdsHost::Impl::adopt_faults() {
    try {
        schedule = faults::FaultSchedule::from_yaml(control.faults().to_string(), ri);
    } catch (const std::exception& e) {
        spdlog::error("cannot apply the clock's fault schedule: {}", e.what());
        return false;
    }
    for (const auto& f : schedule.faults())
        for (const auto& l : locals)
            if (f.kind == faults::Kind::Kill && f.target == l.comp->name() && f.until_step < ri.steps &&
                !opt.rebuild) {
                spdlog::error("member '{}' cannot be restarted by the scheduled {} (this host cannot create it "
                              "anew)", l.comp->name(), f.describe());
                return false;
            }
    return true;
}

// A longer schedule from the clock (a fault injected live): inputs take on the new faults, and the next
// heartbeat acknowledges the version (the clock holds the run until every member has).
bool DdsHost::Impl::adopt_live_faults() {
    faults::FaultSchedule longer;
    try {
        longer = faults::FaultSchedule::from_yaml(control.faults().to_string(), ri);
    } catch (const std::exception& e) {
        spdlog::error("cannot apply the clock's fault schedule: {}", e.what());
        return false;
    }
    const std::size_t first = schedule.adopt(longer);
    for (auto& ch : channels) {
        if (ch->producers.empty()) continue;
        if (ch->faults) {
            ch->faults->extend(first);
            continue;
        }
        std::vector<std::string> names;
        for (auto i : ch->producers) names.push_back(table[i].name().to_string());
        ch->faults = std::make_unique<faults::InputFaults>(schedule, ch->port->topic(), names, *ch->ops, ri);
        if (ch->faults->empty()) ch->faults.reset();
    }
    for (std::size_t i = first; i < schedule.size(); ++i) {
        const faults::Fault& f = schedule.faults()[i];
        if (f.kind == faults::Kind::Rejoin) {
            rejoin(f);
            continue;
        }
        spdlog::warn("fault injected live: {} (step {})", f.describe(), f.from_step);
    }
    faults_version = control.faults_version();
    next_heartbeat_s = 0.0;  // acknowledge at once
    return true;
}

// Member f.target, declared dead, came back (gdnav component --rejoin) and computes again from step f.from_step:
// this host's inputs from it wait for its samples from that step on; or, if it is ours, it starts there.
void DdsHost::Impl::rejoin(const faults::Fault& f) {
    for (auto& l : locals)
        if (l.awaiting_rejoin && l.comp->name() == f.target) {
            l.awaiting_rejoin = false;
            l.next_step = f.from_step;
            spdlog::info("member '{}' rejoins the run at step {} (t = {:.2f} s)", f.target, f.from_step,
                         ri.time_of(f.from_step));
        }
    for (std::uint32_t i = 0; i < table.size(); ++i) {
        if (table[i].name().to_string() != f.target) continue;
        revived_mask |= 1ULL << i;
        dead_mask &= ~(1ULL << i);
        for (auto& ch : channels) {
            if (!ch->lost || std::find(ch->producers.begin(), ch->producers.end(), i) == ch->producers.end())
                continue;
            ch->lost = false;
            ch->revived = true;
            ch->lost_until = f.from_step;
            ch->full.fill(false);
            spdlog::info("input '{}': its producer '{}' rejoins at step {}", ch->port->topic(), f.target,
                         f.from_step);
        }
    }
}

// A restart: member `l` is created anew at step k (the old object goes, with its state).
void DdsHost::Impl::restart(Local& l, std::uint64_t k) {
    const std::string name = l.comp->name();  // a copy: the old member is destroyed below
    l.restarted_at = k;
    std::unique_ptr<Component> fresh = opt.rebuild(name);
    for (std::size_t n = 0; n < l.inputs.size(); ++n) {
        l.inputs[n]->port = fresh->inputs()[n];
        if (l.inputs[n]->lost) l.inputs[n]->port->mark_lost();
    }
    for (std::size_t n = 0; n < l.outputs.size(); ++n) l.outputs[n].port = fresh->outputs()[n];
    for (auto& c : owned)
        if (c.get() == l.comp) c = std::move(fresh), l.comp = c.get();
    l.killed = false;
    spdlog::warn("[{}] step {} t={:.2f} s: restarted by a scheduled fault (created anew)", name, k, ri.time_of(k));
    send_status(l, msg::STATUS_MODE, "restarted by a scheduled fault");
}

// A scheduled kill or restart of member `l` at step k (called every step when the run has faults). Returns
// false when `l` is not stepped at k.
bool DdsHost::Impl::apply_member_faults(Local& l, std::uint64_t k) {
    if (l.restarted_at != k && schedule.restarts_at(l.comp->name(), k)) restart(l, k);
    const std::string& name = l.comp->name();
    if (!schedule.killed(name, k)) return true;
    if (!l.killed) {
        l.killed = true;
        spdlog::warn("[{}] step {} t={:.2f} s: killed by a scheduled fault", name, k, ri.time_of(k));
        send_status(l, msg::STATUS_MODE, "killed by a scheduled fault");
        // The clock stops waiting for it from step k on: report the steps done before (done_every cadence).
        if (k > 0 && in_barrier(l) && k % done_every != 0) send_done(l, k - 1);
    }
    l.next_step = std::min(schedule.alive_again(name, k), ri.steps);
    return false;
}

}  // namespace gdnav::runtime
