#include "runtime/clock.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <fastdds/dds/core/condition/WaitSet.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <spdlog/spdlog.h>

#include "runtime/dds_context.hpp"
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

    msg::Tick tick;
    msg::StepDone done_in;
    msg::ComponentStatus status_in, status_out;
    msg::RunControl control;

    Impl(const RunConfig& r, ClockOptions o) : rc(r), opt(std::move(o)) {
        if (opt.members.empty()) opt.members = rc.member_names();
        for (const auto& n : opt.members) {
            Member m;
            m.name = n;
            m.expected = true;
            members[n] = m;
        }
        dds = std::make_unique<DdsContext>(rc.domain_id, rc.dds_profile, "gdnav.clock");
        tick_writer = dds->writer(topics::kTick, message_ops<msg::Tick>(), kControlWriterProfile);
        control_writer = dds->writer(topics::kRunControl, message_ops<msg::RunControl>(), kLatchedWriterProfile);
        status_writer = dds->writer(topics::kStatus, message_ops<msg::ComponentStatus>(), kControlWriterProfile);
        done_reader = dds->reader(topics::kStepDone, message_ops<msg::StepDone>(), kControlReaderProfile);
        status_reader = dds->reader(topics::kStatus, message_ops<msg::ComponentStatus>(), kControlReaderProfile);
        for (DataReader* r : {done_reader, status_reader}) {
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
        status_out.protocol_version(msg::LOCKSTEP_PROTOCOL_VERSION);
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
            if (m.dead) continue;
            m.last_seen_s = now;
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

    bool all_done() const {
        for (const Member* m : table)
            if (!m->free && !m->dead && m->done_count <= current) return false;
        return true;
    }

    // Lowest number of steps that every live barrier member has completed.
    std::uint64_t min_done() const {
        std::uint64_t m = UINT64_MAX;
        for (const Member* x : table)
            if (!x->free && !x->dead) m = std::min(m, x->done_count);
        return m == UINT64_MAX ? rc.info.steps : m;
    }

    std::string waiting_for() const {
        std::string s;
        for (const Member* m : table)
            if (!m->free && !m->dead && m->done_count <= current) s += (s.empty() ? "" : ", ") + m->name;
        return s;
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
        // A free-running member, or a member declared dead at a wall-clock moment, makes the outputs timing-dependent.
        bool timing = false;
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
                check_liveness(now);
                if (aborted) return finish(kExitAborted, now);
                if (!tick_pending && all_done()) {
                    last_progress_s = now;
                    current = min_done();
                    if (current >= rc.info.steps) {
                        current = rc.info.steps;
                        return finish(kExitOk, now);
                    }
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
