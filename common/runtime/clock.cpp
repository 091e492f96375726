#include "runtime/clock.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <fastdds/dds/core/condition/WaitSet.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <spdlog/spdlog.h>
#include <yaml-cpp/yaml.h>

#include "runtime/dds_context.hpp"
#include "runtime/security/security.hpp"
#include "runtime/graph.hpp"
#include "runtime/lockstep.hpp"
#include "runtime/messages.hpp"
#include "runtime/process_signals.hpp"

namespace gdnav::runtime {

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::Duration_t;

namespace {
struct Member {
    std::string name;
    std::string host;
    std::string inputs;
    std::string outputs;
    bool expected{false};
    bool free{false};
    bool present{false};
    bool ready{false};
    bool dead{false};
    std::uint64_t done_count{0};  // steps 0 .. done_count-1 reported done (members step in order)
    double last_seen_s{0.0};
    std::uint64_t dead_at_step{0};
    std::string dead_reason;
    std::uint32_t faults_version{0};  // fault schedule the member has adopted
};
}  // namespace

struct Clock::Impl {
    const RunConfig& rc;
    ClockOptions opt;
    std::unique_ptr<DdsContext> dds;
    DataWriter* tick_writer{nullptr};
    DataWriter* control_writer{nullptr};
    DataWriter* status_writer{nullptr};
    DataReader* done_reader{nullptr};
    DataReader* status_reader{nullptr};
    DataReader* fault_reader{nullptr};
    WaitSet waitset;

    std::map<std::string, Member> members;
    std::vector<Member*> table;  // index = member index
    enum class Phase { Gather, Configured, Running } phase{Phase::Gather};
    std::uint64_t current{0};
    std::uint64_t dead_mask{0};
    double start_s{0.0}, run_start_s{0.0}, last_progress_s{0.0}, next_log_s{0.0}, next_hb_s{0.0};
    double last_tick_sent_s{0.0};
    double configured_s{0.0};   // when the member table was sent (matching timeout counts from here)
    double next_wait_log_s{0.0};
    std::set<std::string> refused;  // members refused for a protocol version mismatch (logged once)
    bool tick_pending{false};
    std::string host_id{host_identity()};
    // The fault schedule: the run config's, grown by faults injected live (gdnav fault). Members acknowledge each
    // version (ComponentStatus.faults_version) before the clock lets the run reach the step a new fault acts at.
    faults::FaultSchedule schedule{rc.faults};
    std::uint32_t faults_version{0};
    bool adopting{false};
    std::vector<std::string> rejoined;  // members that came back after being declared dead
    double adopt_start_s{0.0};

    msg::Tick tick;
    msg::StepDone done_in;
    msg::ComponentStatus status_in, status_out;
    msg::RunControl control;
    msg::FaultRequest fault_in;

    Impl(const RunConfig& r, ClockOptions o) : rc(r), opt(std::move(o)) {
        if (opt.members.empty()) opt.members = rc.member_names();
        for (const auto& n : opt.members) {
            Member m;
            m.name = n;
            m.expected = true;
            members[n] = m;
        }
        dds = std::make_unique<DdsContext>(rc.domain_id, rc.dds_profile, "gdnav.clock", rc.security_dir,
                                           security::kClockIdentity);
        tick_writer = dds->writer(topics::kTick, message_ops<msg::Tick>(), kControlWriterProfile);
        control_writer = dds->writer(topics::kRunControl, message_ops<msg::RunControl>(), kLatchedWriterProfile);
        status_writer = dds->writer(topics::kStatus, message_ops<msg::ComponentStatus>(), kControlWriterProfile);
        done_reader = dds->reader(topics::kStepDone, message_ops<msg::StepDone>(), kControlReaderProfile);
        status_reader = dds->reader(topics::kStatus, message_ops<msg::ComponentStatus>(), kControlReaderProfile);
        fault_reader = dds->reader(topics::kFaultRequest, message_ops<msg::FaultRequest>(), kControlReaderProfile);
        for (DataReader* r : {done_reader, status_reader, fault_reader}) {
            r->get_statuscondition().set_enabled_statuses(StatusMask::data_available());
            waitset.attach_condition(r->get_statuscondition());
        }
    }

    void heartbeat(double now) {
        if (now < next_hb_s) return;
        next_hb_s = now + kHeartbeatPeriodS;
        status_out.run_id(rc.info.run_index);
        status_out.step(current);
        status_out.t_s(rc.info.time_of(current));
        status_out.member(kClockName);
        status_out.host(host_id);
        status_out.kind(msg::STATUS_HEARTBEAT);
        status_out.message("");
        status_out.protocol_version(msg::LOCKSTEP_PROTOCOL_VERSION);
        status_out.faults_version(faults_version);
        status_writer->write(&status_out);
        // While waiting inside a step, re-send the current Tick: members see the clock alive and the dead set.
        if (phase == Phase::Running && now - last_tick_sent_s > kHeartbeatPeriodS && !tick_pending) send_tick(now);
    }

    void send_tick(double now) {
        tick.stamp().run_id(rc.info.run_index);
        tick.stamp().step(current);
        tick.stamp().t_s(rc.info.time_of(current));
        tick.dead_mask(dead_mask);
        tick.last(current + 1 == rc.info.steps);
        tick_writer->write(&tick);
        last_tick_sent_s = now;
    }

    void send_control(msg::RunCommand cmd, const std::string& reason) {
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

    void read_status(double now) {
        SampleInfo info;
        while (status_reader->take_next_sample(&status_in, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data || status_in.run_id() != rc.info.run_index) continue;
            const std::string name = status_in.member().to_string();
            if (name == kClockName) {
                if (status_in.host().to_string() != host_id) spdlog::warn("another clock ({}) on this domain and run", status_in.host());
                continue;
            }
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
                if (!status_in.free_running() || phase != Phase::Gather) continue;  // not part of this run
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
                if (m.free && m.expected)
                    spdlog::info("member '{}' is free-running (not in the barrier; run not reproducible)", name);
            }
            if (status_in.kind() == msg::STATUS_READY) m.ready = true;
            if (status_in.kind() == msg::STATUS_MODE)
                spdlog::info("[{}] t={:.2f} s: {}", name, status_in.t_s(), status_in.message().to_string());
            if (status_in.kind() == msg::STATUS_ERROR || status_in.kind() == msg::STATUS_EXIT)
                if (phase == Phase::Running) declare_dead(m, "it reported: " + status_in.message().to_string(), now);
        }
    }

    void read_done(double now) {
        SampleInfo info;
        while (done_reader->take_next_sample(&done_in, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data || done_in.run_id() != rc.info.run_index) continue;
            if (done_in.member_index() >= table.size()) continue;
            Member& m = *table[done_in.member_index()];
            m.last_seen_s = now;
            if (!m.dead && done_in.step() + 1 > m.done_count) m.done_count = done_in.step() + 1;
        }
    }

    bool aborted{false};
    std::string abort_reason;

    void declare_dead(Member& m, const std::string& why, double now) {
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

    void check_liveness(double now) {
        for (Member* m : table)
            // Free-running members too: a disconnected hardware member is declared dead, its consumers stop holding
            // its last sample (they see the input lost).
            if (!m->dead && now - m->last_seen_s > rc.member_timeout_s)
                declare_dead(*m, "no heartbeat for " + fmt::format("{:.1f}", now - m->last_seen_s) + " s", now);
    }

    // Steps a member has completed, counting the steps a scheduled kill keeps it from (it is not stepped then).
    std::uint64_t effective_done(const Member& m) const {
        if (schedule.empty() || !schedule.killed(m.name, m.done_count)) return m.done_count;
        return std::min(schedule.alive_again(m.name, m.done_count), rc.info.steps);
    }

    bool all_done() const {
        for (const Member* m : table)
            if (!m->free && !m->dead && effective_done(*m) <= current) return false;
        return true;
    }

    // Lowest number of steps that every live barrier member has completed.
    std::uint64_t min_done() const {
        std::uint64_t m = UINT64_MAX;
        for (const Member* x : table)
            if (!x->free && !x->dead) m = std::min(m, effective_done(*x));
        return m == UINT64_MAX ? rc.info.steps : m;
    }

    std::string waiting_for() const {
        std::string s;
        for (const Member* m : table)
            if (!m->free && !m->dead && effective_done(*m) <= current) s += (s.empty() ? "" : ", ") + m->name;
        return s;
    }

    // An essential member killed by a scheduled fault at the step about to start ends the run, as its death would.
    // A fault injected live (gdnav fault): stamped with the first step no member can have reached, validated, sent
    // to every member; the run waits at the current step until all live members have adopted it.
    void read_fault_requests(double now) {
        SampleInfo info;
        while (fault_reader->take_next_sample(&fault_in, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data || fault_in.run_id() != rc.info.run_index) continue;
            const std::string id = std::to_string(fault_in.request_id());
            const std::string text = fault_in.fault().to_string();
            std::string error;
            if (phase != Phase::Running) error = "the run is not running yet (wait for step 0)";
            std::uint64_t at = current + rc.window_steps + 2;
            try {
                const YAML::Node e = YAML::Load(text);
                if (e.IsMap() && e["kind"] && e["kind"].as<std::string>() == "delay" && e["steps"])
                    at += e["steps"].as<std::uint64_t>();  // the members' history of the delayed samples starts now
            } catch (const std::exception&) {
                // malformed: add_live names the problem
            }
            if (error.empty() && at >= rc.info.steps) error = "the run ends before step " + std::to_string(at);
            if (error.empty()) {
                try {
                    std::map<std::string, faults::MemberPorts> ports;
                    for (const Member* m : table) {
                        auto& p = ports[m->name];
                        p.outputs = split_topics(m->outputs);
                        p.external = rc.is_external(m->name) || m->free;
                    }
                    const faults::Fault& f = schedule.add_live(text, at, rc.info, ports);
                    ++faults_version;
                    adopting = true;
                    adopt_start_s = now;
                    send_control(msg::RUN_FAULTS, "");
                    write_faults();
                    const std::string what = "fault " + id + " accepted: " + f.describe() + " (step " +
                                             std::to_string(f.from_step) + ")";
                    spdlog::warn("{}", what);
                    send_clock_status(msg::STATUS_MODE, what);
                    continue;
                } catch (const std::exception& e) {
                    error = e.what();
                }
            }
            spdlog::error("fault {} refused: {}", id, error);
            send_clock_status(msg::STATUS_ERROR, "fault " + id + " refused: " + error);
        }
    }

    // A member declared dead is back (gdnav component --rejoin), matched with the others: it computes again from the
    // first step no member can have reached; every member learns it through a FAULTS schedule with a rejoin entry,
    // and the run waits until all (the newcomer too) have adopted it.
    void accept_rejoin(Member& m, const std::string& host, double now) {
        const std::uint64_t at = current + rc.window_steps + 2;
        if (at >= rc.info.steps) return;
        std::map<std::string, faults::MemberPorts> ports;
        for (const Member* x : table) ports[x->name].outputs = split_topics(x->outputs);
        const faults::Fault& f = schedule.add_live("{target: " + m.name + ", kind: rejoin}", at, rc.info, ports);
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

    bool all_adopted() const {
        for (const Member* m : table)
            if (!m->dead && !m->free && m->faults_version < faults_version) return false;
        return true;
    }

    void send_clock_status(msg::StatusKind kind, const std::string& message) {
        status_out.run_id(rc.info.run_index);
        status_out.step(current);
        status_out.t_s(rc.info.time_of(current));
        status_out.member(kClockName);
        status_out.host(host_id);
        status_out.kind(kind);
        status_out.message(message.substr(0, 1024));
        status_out.protocol_version(msg::LOCKSTEP_PROTOCOL_VERSION);
        status_out.faults_version(faults_version);
        status_writer->write(&status_out);
    }

    // <out>/faults.yaml: the schedule as applied (the run config's faults and those injected live, with the step
    // they took effect at), for `gdnav run --faults FILE` to reproduce the run.
    void write_faults() const {
        if (rc.out_dir.empty() || schedule.empty()) return;
        std::error_code ec;
        std::filesystem::create_directories(rc.out_dir, ec);
        std::ofstream f(std::filesystem::path(rc.out_dir) / "faults.yaml");
        f << "# The fault schedule of this run as applied (scheduled and injected live).\n"
             "# Reproduce the run: gdnav run --scenario <run.yaml> --faults <this file> (any layout)\n"
          << schedule.to_yaml() << "\n";
    }

    // Members may be done beyond the kill step (the barrier skips a killed member): the run ends at the kill step.
    bool essential_killed() {
        for (const auto& f : schedule.faults())
            if (f.kind == faults::Kind::Kill && f.from_step <= current &&
                std::find(rc.essential.begin(), rc.essential.end(), f.target) != rc.essential.end()) {
                current = f.from_step;
                aborted = true;
                abort_reason = "essential member '" + f.target + "' killed by a scheduled fault at step " +
                               std::to_string(current);
                return true;
            }
        return false;
    }

    void gather(double now) {
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
    bool check_gather_timeouts(double now) {
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

    bool everyone_ready() {
        std::set<std::string> hosts;
        for (Member* m : table) {
            if (!m->ready && !m->free) return false;
            hosts.insert(m->host);
        }
        PublicationMatchedStatus st;
        tick_writer->get_publication_matched_status(st);
        return st.current_count >= static_cast<int>(hosts.size());
    }

    void log_progress(double now, bool force) {
        if (!opt.progress || (!force && now < next_log_s)) return;
        next_log_s = now + 2.0;
        const double wall = std::max(now - run_start_s, 1e-9);
        const double sps = static_cast<double>(current) / wall;
        spdlog::info("step {}/{} ({:.0f}%), t = {:.1f} s, {:.0f} steps/s, {:.1f}x real time", current, rc.info.steps,
                     100.0 * static_cast<double>(current) / static_cast<double>(rc.info.steps),
                     rc.info.time_of(current), sps, sps * rc.info.dt_s);
    }

    void write_summary(bool completed, double now) {
        if (rc.out_dir.empty()) return;
        std::error_code ec;
        std::filesystem::create_directories(rc.out_dir, ec);
        std::ofstream f(std::filesystem::path(rc.out_dir) / "clock_summary.yaml");
        const double wall = now - run_start_s;
        f << "completed: " << (completed ? "true" : "false") << "\n";
        f << "steps_done: " << (completed ? rc.info.steps : current) << "\n";
        f << "wall_s: " << wall << "\n";
        f << "steps_per_s: " << (wall > 0 ? static_cast<double>(completed ? rc.info.steps : current) / wall : 0.0) << "\n";
        if (!completed) f << "abort_reason: \"" << abort_reason << "\"\n";
        f << "dead_members:\n";
        for (Member* m : table)
            if (m->dead) f << "  - {name: " << m->name << ", step: " << m->dead_at_step << "}\n";
        f << "rejoined_members: [";
        for (std::size_t i = 0; i < rejoined.size(); ++i) f << (i ? ", " : "") << rejoined[i];
        f << "]\n";
        // A free-running member, or a member declared dead at a wall-clock moment, makes the outputs timing-dependent.
        bool timing = !rejoined.empty();
        for (Member* m : table) timing = timing || m->free || m->dead;
        f << "reproducible: " << (timing ? "false" : "true") << "\n";
    }

    int finish(int code, double now) {
        if (code == kExitOk) {
            send_control(msg::RUN_STOP, "");
            log_progress(now, true);
            spdlog::info("run complete: {} steps in {:.2f} s", rc.info.steps, now - run_start_s);
        } else {
            send_control(msg::RUN_ABORT, abort_reason);
            spdlog::error("run aborted: {}", abort_reason);
        }
        write_summary(code == kExitOk, now);
        control_writer->wait_for_acknowledgments(Duration_t(2, 0));
        return code;
    }

    int loop() {
        start_s = steady_now_s();
        ConditionSeq active;
        while (true) {
            double now = steady_now_s();
            double wait = kWaitSliceS;
            if (tick_pending && rc.realtime > 0.0) {
                const double target = run_start_s + static_cast<double>(current) * rc.info.dt_s / rc.realtime;
                wait = std::clamp(target - now, 0.0, kWaitSliceS);
                if (wait <= 0.0) {
                    tick_pending = false;
                    send_tick(now);
                    wait = kWaitSliceS;
                }
            }
            waitset.wait(active, Duration_t(0, static_cast<std::uint32_t>(wait * 1e9)));
            now = steady_now_s();
            if (stop_requested()) {
                abort_reason = "clock interrupted by signal " + std::to_string(stop_signal());
                return finish(kExitInterrupted, now);
            }
            read_status(now);
            if (phase == Phase::Gather) {
                gather(now);
                if (phase == Phase::Gather && check_gather_timeouts(now)) return finish(kExitStartup, now);
            } else if (phase == Phase::Configured) {
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
                    return finish(kExitStartup, now);
                }
                check_liveness(now);
            } else {
                read_done(now);
                read_fault_requests(now);
                check_liveness(now);
                if (aborted) return finish(kExitAborted, now);
                if (adopting) {
                    if (!all_adopted()) {
                        if (now - adopt_start_s > rc.stall_timeout_s) {
                            std::string late;
                            for (const Member* m : table)
                                if (!m->dead && !m->free && m->faults_version < faults_version)
                                    late += (late.empty() ? "" : ", ") + m->name;
                            aborted = true;
                            abort_reason = "fault schedule version " + std::to_string(faults_version) +
                                           " not adopted within " + fmt::format("{:.0f}", rc.stall_timeout_s) +
                                           " s by: " + late;
                            return finish(kExitAborted, now);
                        }
                        heartbeat(now);
                        continue;
                    }
                    adopting = false;
                    spdlog::info("fault schedule version {} adopted by every member", faults_version);
                }
                if (!tick_pending && all_done()) {
                    last_progress_s = now;
                    current = min_done();
                    if (current >= rc.info.steps) {
                        current = rc.info.steps;
                        return finish(kExitOk, now);
                    }
                    if (!schedule.empty() && essential_killed()) return finish(kExitAborted, now);
                    if (rc.realtime > 0.0) {
                        tick_pending = true;
                    } else {
                        send_tick(now);
                    }
                    log_progress(now, false);
                    heartbeat(now);
                    continue;  // skip waiting: members answer fast
                }
                if (now - last_progress_s > rc.stall_timeout_s) {
                    aborted = true;
                    abort_reason = "stalled at step " + std::to_string(current) + " for " +
                                   fmt::format("{:.0f}", rc.stall_timeout_s) + " s waiting for: " + waiting_for();
                    return finish(kExitAborted, now);
                }
            }
            heartbeat(now);
        }
    }
};

Clock::Clock(const RunConfig& rc, ClockOptions opt) : impl_(std::make_unique<Impl>(rc, std::move(opt))) {}
Clock::~Clock() = default;
int Clock::run() { return impl_->loop(); }

}  // namespace gdnav::runtime
