// The host's side of the control plane: RunControl, Ticks, heartbeats, the member table (part of DdsHost::Impl).
#include "dds/host/host_impl.hpp"

#include <algorithm>

#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <spdlog/spdlog.h>

#include "framework/graph.hpp"
#include "dds/host/mirror.hpp"

namespace gdnav::runtime {

using namespace eprosima::fastdds::dds;

void DdsHost::Impl::send_status(const Local& l, msg::StatusKind kind, const std::string& message) {
    status_out.run_id(ri.run_index);
    status_out.step(l.next_step == 0 ? 0 : l.next_step - 1);
    status_out.t_s(ri.time_of(status_out.step()));
    status_out.member(l.comp->name());
    status_out.host(host_id);
    status_out.kind(kind);
    status_out.inputs(join_topics(input_topics(*l.comp)));
    status_out.outputs(join_topics(output_topics(*l.comp)));
    status_out.free_running(!in_barrier(l));  // an observer: no outputs and not in the barrier (docs/protocol.md)
    status_out.message(message);
    status_out.protocol_version(msg::LOCKSTEP_PROTOCOL_VERSION);
    status_out.faults_version(faults_version);
    status_writer->write(&status_out);
}

void DdsHost::Impl::heartbeat(double now) {
    if (now < next_heartbeat_s) return;
    next_heartbeat_s = now + kHeartbeatPeriodS;
    const auto kind = phase == Phase::Ready ? msg::STATUS_READY : msg::STATUS_HEARTBEAT;
    // A rejoining member asks for its step once it is matched with the run's other members.
    for (const auto& l : locals)
        send_status(l, kind, l.awaiting_rejoin && phase != Phase::Announce && phase != Phase::Matching ? "rejoin" : "");
}

// Returns false when the run must end; `code` is then the exit code.
bool DdsHost::Impl::read_control(int& code) {
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

void DdsHost::Impl::adopt_timing() {
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

void DdsHost::Impl::configure_from_table() {
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
    make_deferred_readers();
    phase = Phase::Matching;
}

// An observer's inputs that may read a mirror get their reader once the member table names the producers
// (dds/host/mirror.hpp): the mirror when every producer writes one, else the topic itself (with the stride filter).
void DdsHost::Impl::make_deferred_readers() {
    const auto writes_mirror = [this](const std::string& name) {
        const bool configured = std::any_of(rc.members.begin(), rc.members.end(),
                                            [&](const MemberSpec& m) { return m.name == name; });
        const bool here = std::any_of(locals.begin(), locals.end(),
                                      [&](const Local& l) { return l.comp->name() == name; });
        return configured && !rc.is_external(name) && !here;
    };
    for (auto& l : locals)
        for (Channel* ch : l.inputs) {
            if (ch->reader != nullptr || !ch->deferred) continue;
            std::vector<std::string> names;
            for (auto i : ch->producers) names.push_back(table[i].name().to_string());
            const std::string& topic = ch->port->topic();
            const bool mirror = reads_mirror(ch->port->stride(), !rc.security_dir.empty(), names, writes_mirror);
            ch->reader = mirror ? dds->reader(mirror_topic(topic), *ch->ops, kDataReaderProfile, 1, true)
                                : topic_reader(*ch, true);
            ch->reader->set_listener(&listener, StatusMask::data_available());
            spdlog::debug("member '{}': input '{}' read from {}", l.comp->name(), topic,
                          mirror ? mirror_topic(topic) : "the topic itself");
        }
}

bool DdsHost::Impl::all_matched() {
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
            // An observer may read the topic's mirror instead (dds/host/mirror.hpp): its reader is matched there.
            const int mirrored = o.mirror ? o.mirror_matched->readers.load() : 0;
            PublicationMatchedStatus st;
            o.writer->get_publication_matched_status(st);
            if (st.current_count + mirrored < expected) return false;
        }
    }
    SubscriptionMatchedStatus ts;
    tick_reader->get_subscription_matched_status(ts);
    PublicationMatchedStatus ds;
    done_writer->get_publication_matched_status(ds);
    return ts.current_count >= 1 && ds.current_count >= 1;
}

void DdsHost::Impl::read_ticks(double now) {
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

void DdsHost::Impl::apply_dead_mask() {
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

void DdsHost::Impl::read_status(double now) {
    SampleInfo info;
    while (status_reader->take_next_sample(&status_in, &info) == ReturnCode_t::RETCODE_OK) {
        if (info.valid_data && status_in.member().to_string() == kClockName && status_in.run_id() == ri.run_index)
            last_clock_s = now;
    }
}

}  // namespace gdnav::runtime
