#include "runtime/dds_host.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <map>
#include <mutex>
#include <set>

#include <fastdds/dds/core/condition/WaitSet.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <spdlog/spdlog.h>

#include "runtime/dds_context.hpp"
#include "runtime/security/security.hpp"
#include "runtime/faults/input_faults.hpp"
#include "runtime/graph.hpp"
#include "runtime/host_inbox.hpp"
#include "runtime/lateness.hpp"
#include "runtime/lockstep.hpp"
#include "runtime/messages.hpp"
#include "runtime/process_signals.hpp"

namespace gdnav::runtime {

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::Duration_t;

using host::Channel;
using host::Local;

struct DdsHost::Impl {
    const RunConfig& rc;
    HostOptions opt;
    // The run's timing: from the local config, replaced by the clock's CONFIGURE (protocol version >= 1), so a
    // member that knows only the domain and the run id (an external client) steps exactly like a built-in one.
    RunInfo ri{rc.info};
    std::uint64_t window_steps{rc.window_steps};
    std::uint64_t done_every{rc.done_every()};
    double member_timeout_s{rc.member_timeout_s};
    faults::FaultSchedule schedule;  // from CONFIGURE, grown by FAULTS (faults injected live)
    std::uint32_t faults_version{0};
    // How long to wait for the member table: start-up, plus the join time of external members.
    double announce_timeout_s{rc.startup_timeout_s + (rc.external.empty() ? 0.0 : rc.join_timeout_s)};
    std::vector<std::unique_ptr<Component>> owned;
    std::vector<Local> locals;
    std::vector<std::unique_ptr<Channel>> channels;
    std::unique_ptr<DdsContext> dds;
    DataReader* tick_reader{nullptr};
    DataReader* control_reader{nullptr};
    DataReader* status_reader{nullptr};
    DataWriter* done_writer{nullptr};
    DataWriter* status_writer{nullptr};
    WaitSet waitset;  // control-plane readers: RunControl and ComponentStatus (periodic work between waits)

    // Data and Tick readers are served from Fast DDS's listener threads (on_data_available): the step's work is
    // done in the thread that received the sample, which saves a thread hand-over per sample (measured 10-45%
    // faster on 2.9). One recursive mutex serialises everything; a write from inside a callback may deliver to a
    // reader of this very process synchronously, so re-entrant calls only fill inboxes (in_advance).
    // Listener threads never block on the mutex (Fast DDS may call them with a reader lock held, and the lock
    // holder may be taking from that reader): they raise `pending` and try_lock; whoever holds the lock drains
    // again before leaving (pump()).
    struct DataListener final : DataReaderListener {
        Impl* host{nullptr};
        void on_data_available(DataReader*) override { host->pump(); }
    } listener;
    std::recursive_mutex mtx;
    std::atomic<bool> pending{false};
    bool in_advance{false};
    bool not_in_table{false};
    bool closing{false};

    enum class Phase { Announce, Matching, Ready, Running } phase{Phase::Announce};
    std::vector<msg::MemberInfo> table;
    std::uint64_t tick_step{0};
    bool have_tick{false};
    std::uint64_t dead_mask{0};
    std::uint64_t revived_mask{0};  // members that rejoined: their old dead bit no longer counts
    double last_clock_s{0.0};
    double start_s{0.0};
    double next_heartbeat_s{0.0};
    std::string host_id{host_identity()};

    msg::Tick tick;
    msg::RunControl control;
    msg::ComponentStatus status_in;
    msg::ComponentStatus status_out;
    msg::StepDone done;

    Impl(const RunConfig& r, std::vector<std::unique_ptr<Component>> m, HostOptions o)
        : rc(r), opt(o), owned(std::move(m)) {}

    ~Impl() {
        for (auto& c : channels) {
            c->ops->destroy(c->scratch);
            c->ops->destroy(c->latest);
            for (void* s : c->slot) c->ops->destroy(s);
        }
        dds.reset();
    }

    void setup() {
        std::vector<Component*> raw;
        for (auto& c : owned) raw.push_back(c.get());
        const Graph g = build_graph(raw);  // local step order (zero-lag edges inside this process)
        std::string pname = "gdnav";
        std::vector<std::string> hosted;
        for (auto* c : g.order) {
            pname += "." + c->name();
            hosted.push_back(c->name());
        }
        dds = std::make_unique<DdsContext>(rc.domain_id, rc.dds_profile, pname, rc.security_dir,
                                           security::process_identity(hosted));
        tick_reader = dds->reader(topics::kTick, message_ops<msg::Tick>(), kControlReaderProfile);
        control_reader = dds->reader(topics::kRunControl, message_ops<msg::RunControl>(), kLatchedReaderProfile);
        status_reader = dds->reader(topics::kStatus, message_ops<msg::ComponentStatus>(), kControlReaderProfile);
        done_writer = dds->writer(topics::kStepDone, message_ops<msg::StepDone>(), kControlWriterProfile);
        status_writer = dds->writer(topics::kStatus, message_ops<msg::ComponentStatus>(), kControlWriterProfile);
        for (Component* c : g.order) {
            Local l;
            l.comp = c;
            l.awaiting_rejoin = opt.rejoin;
            for (InputBase* in : c->inputs()) {
                auto ch = std::make_unique<Channel>();
                ch->port = in;
                ch->ops = &in->ops();
                ch->reader = dds->reader(in->topic(), in->ops(), kDataReaderProfile);
                ch->scratch = ch->ops->create();
                ch->latest = ch->ops->create();
                for (auto& s : ch->slot) s = ch->ops->create();
                l.inputs.push_back(ch.get());
                channels.push_back(std::move(ch));
            }
            for (OutputBase* o : c->outputs())
                l.outputs.push_back(host::make_output(o, dds->writer(o->topic(), o->ops(), kDataWriterProfile)));
            locals.push_back(std::move(l));
        }
        host::route_locally(locals);
        for (DataReader* r : {control_reader, status_reader}) {
            StatusCondition& cond = r->get_statuscondition();
            cond.set_enabled_statuses(StatusMask::data_available());
            waitset.attach_condition(cond);
        }
        listener.host = this;
    }

    std::vector<DataReader*> data_readers() {
        std::vector<DataReader*> v{tick_reader};
        for (auto& c : channels) v.push_back(c->reader);
        return v;
    }

    // New Tick or data sample (listener threads, and the main loop after its own work).
    void pump() {
        pending.store(true);
        while (pending.load()) {
            if (!mtx.try_lock()) return;  // the holder sees `pending` before it leaves
            pending.store(false);
            if (!closing) process_data(steady_now_s());
            mtx.unlock();
        }
    }

    void process_data(double now) {
        read_ticks(now);
        for (auto& l : locals)
            for (Channel* ch : l.inputs) read_data(l, *ch);
        if (in_advance) return;
        in_advance = true;
        while (advance()) {
        }
        in_advance = false;
    }


    void send_status(const Local& l, msg::StatusKind kind, const std::string& message) {
        status_out.run_id(ri.run_index);
        status_out.step(l.next_step == 0 ? 0 : l.next_step - 1);
        status_out.t_s(ri.time_of(status_out.step()));
        status_out.member(l.comp->name());
        status_out.host(host_id);
        status_out.kind(kind);
        status_out.inputs(join_topics(input_topics(*l.comp)));
        status_out.outputs(join_topics(output_topics(*l.comp)));
        status_out.free_running(opt.free_running);
        status_out.message(message);
        status_out.protocol_version(msg::LOCKSTEP_PROTOCOL_VERSION);
        status_out.faults_version(faults_version);
        status_writer->write(&status_out);
    }

    void heartbeat(double now) {
        if (now < next_heartbeat_s) return;
        next_heartbeat_s = now + kHeartbeatPeriodS;
        const auto kind = phase == Phase::Ready ? msg::STATUS_READY : msg::STATUS_HEARTBEAT;
        // A rejoining member asks for its step once it is matched with the run's other members.
        for (const auto& l : locals)
            send_status(l, kind, l.awaiting_rejoin && phase != Phase::Announce && phase != Phase::Matching ? "rejoin" : "");
    }

    // Returns false when the run must end; `code` is then the exit code.
    bool read_control(int& code) {
        SampleInfo info;
        while (control_reader->take_next_sample(&control, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data || control.run_id() != ri.run_index) continue;
            switch (control.command()) {
                case msg::RUN_CONFIGURE:
                case msg::RUN_FAULTS:
                    if (phase != Phase::Announce && control.command() == msg::RUN_FAULTS &&
                        control.faults_version() > faults_version && !adopt_live_faults()) {
                        code = kExitStartup;
                        return false;
                    }
                    if (phase != Phase::Announce) break;
                    // A rejoining member may see only FAULTS samples (they carry the table as well).
                    if (control.command() == msg::RUN_FAULTS && !opt.rejoin) break;
                    if (control.protocol_version() != msg::LOCKSTEP_PROTOCOL_VERSION) {
                        spdlog::error("the clock speaks lockstep protocol version {}, this member speaks {}; "
                                      "cannot join (docs/protocol.md, 'Versioning')",
                                      control.protocol_version(), msg::LOCKSTEP_PROTOCOL_VERSION);
                        code = kExitStartup;
                        return false;
                    }
                    adopt_timing();
                    if (!adopt_faults()) {
                        code = kExitStartup;
                        return false;
                    }
                    faults_version = control.faults_version();
                    configure_from_table();
                    // The clock is alive now: a member started long before it must not count that wait as silence.
                    last_clock_s = steady_now_s();
                    break;
                case msg::RUN_STOP:
                    spdlog::debug("host {}: STOP received", host_id);
                    code = kExitOk;
                    return false;
                case msg::RUN_ABORT:
                    spdlog::error("run aborted by the clock: {}", control.reason().to_string());
                    code = kExitAborted;
                    return false;
                default:
                    break;
            }
        }
        return true;
    }

    void adopt_timing() {
        if (control.steps() != ri.steps || control.dt_s() != ri.dt_s || control.t0_s() != ri.t0_s)
            spdlog::debug("timing from the clock: {} steps of {} s from t0 = {} s", control.steps(), control.dt_s(),
                          control.t0_s());
        ri.steps = control.steps();
        ri.dt_s = control.dt_s();
        ri.t0_s = control.t0_s();
        window_steps = control.window_steps();
        ri.seed = control.seed();
        done_every = std::max<std::uint64_t>(control.done_every(), 1);
        member_timeout_s = control.member_timeout_s();
    }

    // The clock's fault schedule (protocol version 2). Returns false when it cannot be read.
    bool adopt_faults() {
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
    bool adopt_live_faults() {
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
    void rejoin(const faults::Fault& f) {
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

    void configure_from_table() {
        table.assign(control.members().begin(), control.members().end());
        for (auto& l : locals) {
            l.index = UINT32_MAX;
            for (std::uint32_t i = 0; i < table.size(); ++i)
                if (table[i].name().to_string() == l.comp->name()) l.index = i;
            if (l.index == UINT32_MAX) {
                spdlog::error("member '{}' is not in the clock's member table (another run on this domain, or a "
                              "name the run does not expect)", l.comp->name());
                not_in_table = true;
                continue;
            }
            for (Channel* ch : l.inputs) {
                ch->producers.clear();
                for (std::uint32_t i = 0; i < table.size(); ++i) {
                    const auto outs = split_topics(table[i].outputs().to_string());
                    if (std::find(outs.begin(), outs.end(), ch->port->topic()) != outs.end()) {
                        ch->producers.push_back(i);
                        ch->free = ch->free || table[i].free_running();
                    }
                }
                if (!schedule.empty()) {
                    std::vector<std::string> names;
                    for (auto i : ch->producers) names.push_back(table[i].name().to_string());
                    ch->faults = std::make_unique<faults::InputFaults>(schedule, ch->port->topic(), names, *ch->ops, ri);
                    if (ch->faults->empty()) ch->faults.reset();
                }
                if (ch->producers.empty()) {
                    spdlog::warn("member '{}': no member of this run produces '{}'; input treated as lost",
                                 l.comp->name(), ch->port->topic());
                    ch->lost = true;
                    ch->port->mark_lost();
                }
                if (opt.free_running) ch->free = true;
            }
        }
        phase = Phase::Matching;
    }

    bool all_matched() {
        for (auto& l : locals) {
            for (Channel* ch : l.inputs) {
                SubscriptionMatchedStatus st;
                ch->reader->get_subscription_matched_status(st);
                if (st.current_count < static_cast<int>(ch->producers.size())) return false;
            }
            for (auto& o : l.outputs) {
                int expected = 0;
                for (const auto& m : table)
                    for (const auto& t : split_topics(m.inputs().to_string())) expected += (t == o.port->topic());
                PublicationMatchedStatus st;
                o.writer->get_publication_matched_status(st);
                if (st.current_count < expected) return false;
            }
        }
        SubscriptionMatchedStatus ts;
        tick_reader->get_subscription_matched_status(ts);
        PublicationMatchedStatus ds;
        done_writer->get_publication_matched_status(ds);
        return ts.current_count >= 1 && ds.current_count >= 1;
    }

    void read_ticks(double now) {
        SampleInfo info;
        while (tick_reader->take_next_sample(&tick, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data || tick.stamp().run_id() != ri.run_index) continue;
            last_clock_s = now;
            if (!have_tick || tick.stamp().step() > tick_step) tick_step = tick.stamp().step();
            have_tick = true;
            if (phase == Phase::Ready) phase = Phase::Running;  // a rejoining member sees Ticks while matching
            const std::uint64_t dead = tick.dead_mask() & ~revived_mask;
            if ((dead | dead_mask) != dead_mask) {
                dead_mask |= dead;
                apply_dead_mask();
            }
        }
    }

    void apply_dead_mask() {
        for (auto& ch : channels) {
            if (ch->lost || ch->producers.empty()) continue;
            bool all_dead = true;
            for (auto i : ch->producers) all_dead = all_dead && ((dead_mask >> i) & 1u);
            if (all_dead) {
                ch->lost = true;
                ch->port->mark_lost();
                spdlog::warn("input '{}' lost: its producer was declared dead", ch->port->topic());
            }
        }
    }

    void read_status(double now) {
        SampleInfo info;
        while (status_reader->take_next_sample(&status_in, &info) == ReturnCode_t::RETCODE_OK) {
            if (info.valid_data && status_in.member().to_string() == kClockName && status_in.run_id() == ri.run_index)
                last_clock_s = now;
        }
    }

    void read_data(const Local& l, Channel& ch) {
        SampleInfo info;
        while (ch.reader->take_next_sample(ch.scratch, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data || ch.ops->run_of(ch.scratch) != ri.run_index) continue;
            if (ch.free) {
                ch.ops->copy(ch.latest, ch.scratch);
                ch.has_latest = true;
                continue;
            }
            const std::uint64_t s = ch.ops->step_of(ch.scratch);
            const long at = host::inbox_index(ch, l.next_step, s);
            if (at == host::kOlder) continue;
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

    static void warn_too_far(const Local& l, const Channel& ch, std::uint64_t s) {
        if (l.killed) return;  // a member killed by a fault does not read its inputs
        spdlog::warn("input '{}': sample of step {} is too far ahead of step {}; dropped", ch.port->topic(), s,
                     l.next_step);
    }

    // A local member's output of step k: into the inboxes of the local readers, and on DDS if anyone outside reads it.
    void publish(host::Output& o, std::uint64_t k) {
        for (const auto& r : o.routes)
            if (!host::hand_over(r, locals[r.consumer], o.port->data(), k))
                warn_too_far(locals[r.consumer], *r.channel, k);
        if (o.routes.empty() || host::read_outside(o)) o.writer->write(o.port->data());
    }

    bool inputs_ready(const Local& l, std::uint64_t k) {
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

    void send_done(const Local& l, std::uint64_t k) {
        done.run_id(ri.run_index);
        done.step(k);
        done.member_index(l.index);
        done_writer->write(&done);
    }

    // A restart: member `l` is created anew at step k (the old object goes, with its state).
    void restart(Local& l, std::uint64_t k) {
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
    bool apply_member_faults(Local& l, std::uint64_t k) {
        if (l.restarted_at != k && schedule.restarts_at(l.comp->name(), k)) restart(l, k);
        const std::string& name = l.comp->name();
        if (!schedule.killed(name, k)) return true;
        if (!l.killed) {
            l.killed = true;
            spdlog::warn("[{}] step {} t={:.2f} s: killed by a scheduled fault", name, k, ri.time_of(k));
            send_status(l, msg::STATUS_MODE, "killed by a scheduled fault");
            // The clock stops waiting for it from step k on: report the steps done before (done_every cadence).
            if (k > 0 && !opt.free_running && k % done_every != 0) send_done(l, k - 1);
        }
        l.next_step = std::min(schedule.alive_again(name, k), ri.steps);
        return false;
    }

    // Free inputs of a step about to run: how many steps old the sample used is (once per executed step).
    void record_lateness(const Local& l, std::uint64_t k) {
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
    bool advance() {
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
                if (!inputs_ready(l, k)) break;
                record_lateness(l, k);
                const StepContext ctx{k, ri.time_of(k), ri.dt_s, k + 1 == ri.steps};
                l.comp->step(ctx);
                for (auto& o : l.outputs) {
                    o.port->ops().set_stamp(o.port->data(), ri.run_index, k, ctx.t_s);
                    publish(o, k);
                }
                for (auto& m : l.comp->pending_status()) {
                    spdlog::info("[{}] step {} t={:.2f} s: {}", l.comp->name(), k, ctx.t_s, m);
                    send_status(l, msg::STATUS_MODE, m);
                }
                l.comp->pending_status().clear();
                ++l.next_step;
                if (!opt.free_running && ((k + 1) % done_every == 0 || k + 1 == ri.steps)) send_done(l, k);
                any = true;
            }
        }
        return any;
    }

    // Free-running inputs (hardware-in-the-loop): summary lines and <out>/lateness/<member>.yaml.
    void report_lateness() {
        if (opt.free_running) return;  // a free-running member's own inputs are not a deadline
        for (const auto& l : locals) {
            std::vector<std::pair<std::string, const Lateness*>> inputs;
            for (const Channel* ch : l.inputs)
                if (ch->free) inputs.emplace_back(ch->port->topic(), &ch->lateness);
            runtime::report_lateness(l.comp->name(), inputs, rc.out_dir);
        }
    }

    int loop() {
        start_s = steady_now_s();
        last_clock_s = start_s;
        ConditionSeq active;
        const Duration_t slice(0, static_cast<std::uint32_t>(kWaitSliceS * 1e9));
        int code = kExitOk;
        for (DataReader* r : data_readers()) r->set_listener(&listener, StatusMask::data_available());
        std::unique_lock<std::recursive_mutex> lock(mtx, std::defer_lock);
        while (true) {
            waitset.wait(active, slice);
            lock.lock();
            const double now = steady_now_s();
            if (stop_requested()) {
                spdlog::warn("host {}: stopped by signal {}", host_id, stop_signal());
                code = kExitInterrupted;
                break;
            }
            if (!read_control(code)) break;
            if (not_in_table) {
                code = kExitStartup;
                break;
            }
            read_status(now);
            if (phase == Phase::Matching && all_matched()) {
                phase = Phase::Ready;
                next_heartbeat_s = 0.0;  // report READY at once
            }
            heartbeat(now);
            pending.store(false);
            process_data(now);
            if (phase == Phase::Announce || (phase != Phase::Running && !have_tick)) {
                if (phase == Phase::Announce && now - start_s > announce_timeout_s) {
                    spdlog::error("no clock: no member table from the clock '{}' within {:.1f} s", kClockName,
                                  announce_timeout_s);
                    code = kExitStartup;
                    break;
                }
                if (phase != Phase::Announce && now - last_clock_s > member_timeout_s) {
                    spdlog::error("lost the clock '{}': no Tick or heartbeat for {:.1f} s before the start",
                                  kClockName, now - last_clock_s);
                    code = kExitLostClock;
                    break;
                }
            } else if (now - last_clock_s > member_timeout_s) {
                spdlog::error("lost the clock '{}': no Tick or heartbeat for {:.1f} s (last Tick: step {})", kClockName,
                              now - last_clock_s, tick_step);
                code = kExitLostClock;
                break;
            }
            lock.unlock();
            pump();
        }
        closing = true;
        lock.unlock();
        for (DataReader* r : data_readers()) r->set_listener(nullptr);
        lock.lock();
        for (auto& l : locals) {
            if (code != kExitOk) send_status(l, msg::STATUS_EXIT, "exit code " + std::to_string(code));
            if (!l.killed) l.comp->finish(code == kExitOk);
        }
        report_lateness();
        return code;
    }
};

DdsHost::DdsHost(const RunConfig& rc, std::vector<std::unique_ptr<Component>> members, HostOptions opt)
    : impl_(std::make_unique<Impl>(rc, std::move(members), opt)) {
    impl_->setup();
}

DdsHost::~DdsHost() = default;

int DdsHost::run() { return impl_->loop(); }

}  // namespace gdnav::runtime
