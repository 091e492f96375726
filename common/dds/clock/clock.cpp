// The lockstep clock's main loop: gathering the members, the start, Ticks, the end of the run (state: clock/clock_impl.hpp).
#include "dds/clock/clock_impl.hpp"

#include <unistd.h>

#include <algorithm>

#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <spdlog/spdlog.h>

#include "framework/graph.hpp"
#include "dds/process/process_signals.hpp"

namespace gdnav::dds {

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::Duration_t;

void Clock::Impl::heartbeat(double now) {
    if (now < next_hb_s) return;
    next_hb_s = now + framework::kHeartbeatPeriodS;
    status_out.run_id(rc.info.run_index);
    status_out.step(current);
    status_out.t_s(rc.info.time_of(current));
    status_out.member(framework::kClockName);
    status_out.host(host_id);
    status_out.kind(msg::STATUS_HEARTBEAT);
    status_out.message(rc.out_dir.substr(0, 1024));  // names the run to a clock that meets it (docs/protocol.md)
    status_out.protocol_version(msg::LOCKSTEP_PROTOCOL_VERSION);
    status_out.faults_version(faults_version);
    status_out.run_token(token);
    status_writer->write(&status_out);
    // While waiting inside a step, re-send the current Tick: members see the clock alive and the dead set.
    if (phase == Phase::Running && now - last_tick_sent_s > framework::kHeartbeatPeriodS && !tick_pending)
        send_tick(now);
}

void Clock::Impl::send_tick(double now) {
    tick.stamp().run_id(rc.info.run_index);
    tick.stamp().step(current);
    tick.stamp().t_s(rc.info.time_of(current));
    tick.dead_mask(dead_mask);
    tick.last(current + 1 == rc.info.steps);
    tick.run_token(token);
    tick_writer->write(&tick);
    last_tick_sent_s = now;
}

void Clock::Impl::send_control(msg::RunCommand cmd, const std::string& reason) {
    control.run_id(rc.info.run_index);
    control.command(cmd);
    control.steps(rc.info.steps);
    control.reason(reason);
    control.protocol_version(msg::LOCKSTEP_PROTOCOL_VERSION);
    control.dt_s(rc.info.dt_s);
    control.t0_s(rc.info.t0_s);
    control.window_steps(rc.window_steps);
    control.done_every(rc.done_every());
    control.member_timeout_s(rc.member_timeout_s);
    control.seed(rc.info.seed);
    control.faults(schedule.to_yaml());
    control.faults_version(faults_version);
    control.run_token(token);
    control.members().clear();
    for (Member* m : table) {
        msg::MemberInfo mi;
        mi.name(m->name);
        mi.inputs(m->inputs);
        mi.outputs(m->outputs);
        mi.free_running(m->free);
        control.members().push_back(mi);
    }
    control_writer->write(&control);
}

void Clock::Impl::gather(double now) {
    for (const auto& [n, m] : members)
        if (m.expected && !m.present) return;
    // Table order: expected members in config order, then free-running joiners by name.
    for (const auto& n : opt.members) table.push_back(&members[n]);
    for (auto& [n, m] : members)
        if (!m.expected && m.present) table.push_back(&m);
    for (Member* m : table) m->last_seen_s = now;
    send_control(msg::RUN_CONFIGURE, "");
    phase = Phase::Configured;
    configured_s = now;
    spdlog::info("all {} members present; member table sent", table.size());
}

// Members still missing before the table is sent: built-in ones within startup_timeout_s, external ones within
// join_timeout_s (with a line every 5 s saying what the clock waits for). Returns true when the run must end.
bool Clock::Impl::check_gather_timeouts(double now) {
    std::string builtin, external;
    for (const auto& n : opt.members) {
        const Member& m = members[n];
        if (m.present) continue;
        std::string& list = rc.is_external(n) ? external : builtin;
        list += (list.empty() ? "'" : ", '") + n + "'";
    }
    const double waited = now - start_s;
    if (!external.empty() && now >= next_wait_log_s) {
        next_wait_log_s = now + 5.0;
        spdlog::info("waiting for external member(s) {} on DDS domain {}, run id {} ({:.0f} of {:.0f} s)", external,
                     rc.domain_id, rc.info.run_index, waited, rc.join_timeout_s);
    }
    if (!builtin.empty() && waited > rc.startup_timeout_s) {
        abort_reason = "start-up timeout: members missing after " + fmt::format("{:.0f}", rc.startup_timeout_s) +
                       " s: " + builtin;
        return true;
    }
    if (!external.empty() && waited > rc.join_timeout_s) {
        abort_reason = "external member" + std::string(external.find(',') == std::string::npos ? " " : "s ") +
                       external + " did not join within " + fmt::format("{:.0f}", rc.join_timeout_s) +
                       " s (DDS domain " + std::to_string(rc.domain_id) + ", run id " +
                       std::to_string(rc.info.run_index) + ")";
        return true;
    }
    return false;
}

bool Clock::Impl::everyone_ready() {
    std::set<std::string> hosts;
    for (Member* m : table) {
        if (!m->ready && !m->free) return false;
        hosts.insert(m->host);
    }
    PublicationMatchedStatus st;
    tick_writer->get_publication_matched_status(st);
    return st.current_count >= static_cast<int>(hosts.size());
}

int Clock::Impl::loop() {
    start_s = framework::steady_now_s();
    double last_wake_s = start_s;
    ConditionSeq active;
    while (true) {
        double now = framework::steady_now_s();
        double wait = framework::kWaitSliceS;
        if (tick_pending && rc.realtime > 0.0) {
            const double target = run_start_s + static_cast<double>(current) * rc.info.dt_s / rc.realtime;
            wait = std::clamp(target - now, 0.0, framework::kWaitSliceS);
            if (wait <= 0.0) {
                tick_pending = false;
                send_tick(now);
                wait = framework::kWaitSliceS;
            }
        }
        waitset.wait(active, Duration_t(0, static_cast<std::uint32_t>(wait * 1e9)));
        now = framework::steady_now_s();
        const double stall = framework::own_stall_s(now - last_wake_s);
        last_wake_s = now;
        if (stall > 0.0) {  // the members' silence meanwhile is not counted
            for (Member* m : table) m->last_seen_s += stall;
            spdlog::debug("clock: not scheduled for {:.2f} s; the members' silence meanwhile is not counted", stall);
        }
        if (stop_requested()) {
            abort_reason = "clock interrupted by signal " + std::to_string(stop_signal());
            return finish(framework::kExitInterrupted, now);
        }
        read_status(now);
        const int code = phase == Phase::Claim        ? claim_phase(now)
                         : phase == Phase::Gather     ? gather_phase(now)
                         : phase == Phase::Configured ? configured_phase(now)
                                                      : running_phase(now);
        if (code != kGoOn) return code;
        heartbeat(now);
    }
}

// The domain is this run's when no other clock was heard for kClaimListenS and the domain has shown no other life
// (discovery, another run's member) for kClaimQuietS, or after kClaimLongestS (lockstep.hpp). The clock's own
// heartbeats go out meanwhile, so two clocks started together both refuse rather than share the domain.
int Clock::Impl::claim_phase(double now) {
    if (!rival.empty()) {
        spdlog::error("DDS domain {} is in use by another run ({}); this run (token {}) does not start: choose "
                      "another --domain, or give none to get a free one",
                      rc.domain_id, rival, token_text(token));
        if (opt.ready_fd >= 0) close(opt.ready_fd);
        return framework::kExitStartup;
    }
    if (const std::uint64_t g = dds->participants().generation(); g != participants_seen) {
        participants_seen = g;
        other_life_s = now;
    }
    const double listened = now - start_s;
    if (listened < framework::kClaimListenS) return kGoOn;
    if (listened < framework::kClaimLongestS && now - other_life_s < framework::kClaimQuietS) return kGoOn;
    phase = Phase::Gather;
    if (foreign.count() > 0)
        spdlog::info("DDS domain {}: {} statuses of another run's members heard in {:.1f} s, but not its clock (a run "
                     "that ended): the domain is this run's",
                     rc.domain_id, foreign.count(), listened);
    spdlog::debug("DDS domain {} is free after {:.2f} s of listening: run token {}", rc.domain_id, listened,
                  token_text(token));
    if (opt.ready_fd >= 0) {
        if (write(opt.ready_fd, "1", 1) != 1) spdlog::warn("cannot tell the launcher that the domain is claimed");
        close(opt.ready_fd);
    }
    return gather_phase(now);
}

int Clock::Impl::gather_phase(double now) {
    gather(now);
    if (phase == Phase::Gather && check_gather_timeouts(now)) return finish(framework::kExitStartup, now);
    return kGoOn;
}

int Clock::Impl::configured_phase(double now) {
    if (everyone_ready()) {
        phase = Phase::Running;
        run_start_s = now;
        last_progress_s = now;
        next_log_s = now + 2.0;
        spdlog::info("all members ready; run {} starts ({} steps)", rc.info.run_index, rc.info.steps);
        send_tick(now);
    } else if (now - configured_s > rc.startup_timeout_s) {
        std::string missing;
        for (Member* m : table)
            if (!m->ready && !m->free) missing += (missing.empty() ? "" : ", ") + m->name;
        abort_reason = "start-up timeout: members not ready (DDS matching) after " +
                       fmt::format("{:.0f}", rc.startup_timeout_s) + " s: " + missing;
        return finish(framework::kExitStartup, now);
    }
    check_liveness(now);
    return kGoOn;
}

int Clock::Impl::running_phase(double now) {
    read_done(now);
    read_fault_requests(now);
    check_liveness(now);
    if (aborted) return finish(framework::kExitAborted, now);
    if (adopting) {
        if (!all_adopted()) {
            if (now - adopt_start_s <= rc.stall_timeout_s) return kGoOn;
            std::string late;
            for (const Member* m : table)
                if (!m->dead && !m->free && m->faults_version < faults_version)
                    late += (late.empty() ? "" : ", ") + m->name;
            aborted = true;
            abort_reason = "fault schedule version " + std::to_string(faults_version) + " not adopted within " +
                           fmt::format("{:.0f}", rc.stall_timeout_s) + " s by: " + late;
            return finish(framework::kExitAborted, now);
        }
        adopting = false;
        spdlog::info("fault schedule version {} adopted by every member", faults_version);
    }
    if (!tick_pending && all_done()) return advance_tick(now);
    if (now - last_progress_s > rc.stall_timeout_s) {
        aborted = true;
        abort_reason = "stalled at step " + std::to_string(current) + " for " +
                       fmt::format("{:.0f}", rc.stall_timeout_s) + " s waiting for: " + waiting_for();
        return finish(framework::kExitAborted, now);
    }
    return kGoOn;
}

int Clock::Impl::advance_tick(double now) {
    last_progress_s = now;
    current = min_done();
    if (current >= rc.info.steps) {
        current = rc.info.steps;
        return finish(framework::kExitOk, now);
    }
    if (!schedule.empty() && essential_killed()) return finish(framework::kExitAborted, now);
    if (rc.realtime > 0.0) {
        tick_pending = true;
    } else {
        send_tick(now);
    }
    log_progress(now, false);
    return kGoOn;
}

Clock::Clock(const framework::RunConfig& rc, ClockOptions opt) : impl_(std::make_unique<Impl>(rc, std::move(opt))) {}
Clock::~Clock() = default;
int Clock::run() { return impl_->loop(); }

}  // namespace gdnav::dds
