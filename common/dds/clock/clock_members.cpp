// The clock's view of the members: heartbeats, StepDone, liveness, death, rejoin (part of clock.cpp's Clock::Impl).
#include "dds/clock/clock_impl.hpp"

#include <algorithm>

#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <spdlog/spdlog.h>

#include "framework/graph.hpp"

namespace gdnav::dds {

using namespace eprosima::fastdds::dds;

void Clock::Impl::read_status(double now) {
    SampleInfo info;
    while (status_reader->take_next_sample(&status_in, &info) == ReturnCode_t::RETCODE_OK) {
        if (!info.valid_data) continue;
        const std::string name = status_in.member().to_string();
        if (name == framework::kClockName) {
            clock_status(status_in);
            continue;
        }
        if (!ours(status_in, now) || status_in.run_id() != rc.info.run_index) continue;  // another token first: counted
        if (status_in.protocol_version() != msg::LOCKSTEP_PROTOCOL_VERSION) {
            if (refused.insert(name).second)
                spdlog::error("member '{}' ({}) speaks lockstep protocol version {}, this clock speaks {}: refused "
                              "(docs/protocol.md, 'Versioning')",
                              name, status_in.host().to_string(), status_in.protocol_version(),
                              msg::LOCKSTEP_PROTOCOL_VERSION);
            continue;
        }
        auto it = members.find(name);
        if (it == members.end()) {
            if (!status_in.free_running() || phase > Phase::Gather) continue;  // not part of this run
            if (members.size() >= 63) {  // Tick.dead_mask has 64 bits; RunControl.members holds 64
                if (refused.insert(name).second)
                    spdlog::error("free-running member '{}' refused: a run has at most 63 members", name);
                continue;
            }
            it = members.emplace(name, Member{}).first;
            it->second.name = name;
            it->second.free = true;
            spdlog::info("free-running member '{}' joins (run not reproducible)", name);
        }
        Member& m = it->second;
        if (m.dead && status_in.message().to_string() == "rejoin" && phase == Phase::Running) {
            accept_rejoin(m, status_in.host().to_string(), now);
            continue;
        }
        if (m.dead) continue;
        m.last_seen_s = now;
        m.faults_version = std::max(m.faults_version, status_in.faults_version());
        if (!m.present) {
            m.present = true;
            m.host = status_in.host().to_string();
            m.inputs = status_in.inputs().to_string();
            m.outputs = status_in.outputs().to_string();
            m.free = m.free || status_in.free_running();
            if (rc.is_external(name))
                spdlog::info("external member '{}' joined from {} (inputs: {}; outputs: {})", name, m.host,
                             m.inputs.empty() ? "none" : m.inputs, m.outputs.empty() ? "none" : m.outputs);
            else
                spdlog::debug("member '{}' present on {}", name, m.host);
            if (m.observer() && m.expected)
                spdlog::debug("member '{}' is an observer (no outputs; not in the barrier)", name);
            else if (m.free && m.expected)
                spdlog::info("member '{}' is free-running (not in the barrier; run not reproducible)", name);
        }
        if (status_in.kind() == msg::STATUS_READY && status_in.run_token() == token) m.ready = true;
        if (status_in.kind() == msg::STATUS_HEARTBEAT && status_in.run_token() == token) {
            m.beat_step = status_in.step();
            m.beat_heard = true;
        }
        if (const std::string text = status_in.message().to_string();
            (status_in.kind() == msg::STATUS_HEARTBEAT || status_in.kind() == msg::STATUS_READY) &&
            text.rfind("rejected ", 0) == 0)
            m.rejected = text.substr(9);
        if (status_in.kind() == msg::STATUS_MODE)
            spdlog::info("[{}] t={:.2f} s: {}", name, status_in.t_s(), status_in.message().to_string());
        if (status_in.kind() == msg::STATUS_ERROR || status_in.kind() == msg::STATUS_EXIT)
            if (phase == Phase::Running) declare_dead(m, "it reported: " + status_in.message().to_string(), now);
    }
}

// Any clock but this one is another run: while claiming the domain a reason to refuse, afterwards ignored.
void Clock::Impl::clock_status(const msg::ComponentStatus& s) {
    if (s.run_token() == token) return;  // our own heartbeat
    const std::string host = s.host().to_string();
    if (phase != Phase::Claim) {
        foreign.note(s.run_token(), "clock " + host, "its heartbeat");
        return;
    }
    if (!rival.empty()) return;
    const std::string out = s.message().to_string();
    rival = "its clock on " + host + ", run id " + std::to_string(s.run_id()) + ", token " +
            token_text(s.run_token()) + (out.empty() ? "" : ", output " + out) + ", at step " +
            std::to_string(s.step());
}

// Statuses carry the token of the CONFIGURE their member joined with, or 0 before it has one (it announces itself).
// Announcements count until the run starts (a member gets the table a moment after the clock sent it); a status
// of another token is another run's.
bool Clock::Impl::ours(const msg::ComponentStatus& s, double now) {
    if (s.run_token() == token) return true;
    if (s.run_token() == 0) return phase != Phase::Running;
    if (phase == Phase::Claim) {  // another run's member: its clock is about to be heard (claim_phase says it)
        foreign.count_quietly();
        other_life_s = now;
        return false;
    }
    foreign.note(s.run_token(), fmt::format("'{}' on {}", s.member().to_string(), s.host().to_string()),
                 "ComponentStatus");
    return false;
}

void Clock::Impl::read_done(double now) {
    SampleInfo info;
    while (done_reader->take_next_sample(&done_in, &info) == ReturnCode_t::RETCODE_OK) {
        if (!this_run(info, done_in, "a StepDone writer", "StepDone")) continue;
        if (done_in.member_index() >= table.size()) continue;
        Member& m = *table[done_in.member_index()];
        m.last_seen_s = now;
        if (!m.dead && done_in.step() + 1 > m.done_count) m.done_count = done_in.step() + 1;
    }
}

void Clock::Impl::declare_dead(Member& m, const std::string& why, double now) {
    if (m.dead) return;
    m.dead = true;
    m.dead_at_step = current;
    m.dead_reason = why;
    spdlog::warn("member '{}' declared dead at step {} (t = {:.2f} s): {}", m.name, current, rc.info.time_of(current),
                 why);
    if (std::find(rc.essential.begin(), rc.essential.end(), m.name) != rc.essential.end()) {
        aborted = true;
        abort_reason = "essential member '" + m.name + "' lost at step " + std::to_string(current) + ": " + why;
        return;
    }
    for (std::size_t i = 0; i < table.size(); ++i)
        if (table[i] == &m) dead_mask |= (1ULL << i);
    if (phase == Phase::Running) send_tick(now);
}

void Clock::Impl::check_liveness(double now) {
    for (Member* m : table)
        // Free-running members too: a disconnected hardware member is declared dead, its consumers stop holding
        // its last sample (they see the input lost).
        if (!m->dead && now - m->last_seen_s > rc.member_timeout_s)
            declare_dead(*m, "no heartbeat for " + fmt::format("{:.1f}", now - m->last_seen_s) + " s", now);
}

// Steps a member has completed, counting the steps a scheduled kill keeps it from (it is not stepped then).
std::uint64_t Clock::Impl::effective_done(const Member& m) const {
    if (schedule.empty() || !schedule.killed(m.name, m.done_count)) return m.done_count;
    return std::min(schedule.alive_again(m.name, m.done_count), rc.info.steps);
}

bool Clock::Impl::all_done() const {
    for (const Member* m : table)
        if (!m->free && !m->dead && effective_done(*m) <= current) return false;
    return true;
}

// Lowest number of steps that every live barrier member has completed.
std::uint64_t Clock::Impl::min_done() const {
    std::uint64_t m = UINT64_MAX;
    for (const Member* x : table)
        if (!x->free && !x->dead) m = std::min(m, effective_done(*x));
    return m == UINT64_MAX ? rc.info.steps : m;
}

std::string Clock::Impl::waiting_for() const {
    std::string s;
    for (const Member* m : table)
        if (!m->free && !m->dead && effective_done(*m) <= current)
            s += (s.empty() ? "" : ", ") + m->name +
                 (m->beat_heard ? " (its heartbeat: step " + std::to_string(m->beat_step) + ")" : "");
    return s;
}

// A member declared dead is back (gdnav component --rejoin), matched with the others: it computes again from the
// first step no member can have reached; every member learns it through a FAULTS schedule with a rejoin entry,
// and the run waits until all (the newcomer too) have adopted it.
void Clock::Impl::accept_rejoin(Member& m, const std::string& host, double now) {
    const std::uint64_t at = current + rc.window_steps + 2;
    if (at >= rc.info.steps) return;
    std::map<std::string, framework::faults::MemberPorts> ports;
    for (const Member* x : table) ports[x->name].outputs = framework::split_topics(x->outputs);
    const framework::faults::Fault& f = schedule.add_live("{target: " + m.name + ", kind: rejoin}", at, rc.info, ports);
    m.dead = false;
    m.dead_reason.clear();
    m.host = host;
    m.last_seen_s = now;
    m.done_count = f.from_step;
    m.faults_version = 0;
    for (std::size_t i = 0; i < table.size(); ++i)
        if (table[i] == &m) dead_mask &= ~(1ULL << i);
    ++faults_version;
    adopting = true;
    adopt_start_s = now;
    send_control(msg::RUN_FAULTS, "");
    write_faults();
    rejoined.push_back(m.name);
    spdlog::warn("member '{}' rejoins from {} at step {} (t = {:.2f} s)", m.name, host, f.from_step,
                 rc.info.time_of(f.from_step));
}

bool Clock::Impl::all_adopted() const {
    for (const Member* m : table)
        if (!m->dead && !m->free && m->faults_version < faults_version) return false;
    return true;
}

void Clock::Impl::send_clock_status(msg::StatusKind kind, const std::string& message) {
    status_out.run_id(rc.info.run_index);
    status_out.step(current);
    status_out.t_s(rc.info.time_of(current));
    status_out.member(framework::kClockName);
    status_out.host(host_id);
    status_out.kind(kind);
    status_out.message(message.substr(0, 1024));
    status_out.protocol_version(msg::LOCKSTEP_PROTOCOL_VERSION);
    status_out.faults_version(faults_version);
    status_out.run_token(token);
    status_writer->write(&status_out);
}

// An essential member killed by a scheduled fault at the step about to start ends the run, as its death would.
// Members may be done beyond the kill step (the barrier skips a killed member): the run ends at the kill step.
bool Clock::Impl::essential_killed() {
    for (const auto& f : schedule.faults())
        if (f.kind == framework::faults::Kind::Kill && f.from_step <= current &&
            std::find(rc.essential.begin(), rc.essential.end(), f.target) != rc.essential.end()) {
            current = f.from_step;
            aborted = true;
            abort_reason = "essential member '" + f.target + "' killed by a scheduled fault at step " +
                           std::to_string(current);
            return true;
        }
    return false;
}

}  // namespace gdnav::dds
