// The DDS host: set-up, the main loop and the listener pump (state: host/host_impl.hpp).
#include "dds/host/host_impl.hpp"

#include <algorithm>

#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <spdlog/spdlog.h>

#include "framework/graph.hpp"
#include "dds/host/mirror.hpp"
#include "dds/process/process_priority.hpp"
#include "dds/process/process_signals.hpp"
#include "dds/security/security.hpp"

namespace gdnav::runtime {

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::Duration_t;

namespace {

// An observer as the host treats it (docs/protocol.md §6.4): observer() and no outputs to hold anybody up.
bool hosted_as_observer(const Component& c) { return c.observer() && c.outputs().empty(); }

}  // namespace

void DdsHost::Impl::setup() {
    std::vector<Component*> raw;
    for (auto& c : owned) raw.push_back(c.get());
    const Graph g = build_graph(raw);  // local step order (zero-lag edges inside this process)
    std::string pname = "gdnav";
    std::vector<std::string> hosted;
    for (auto* c : g.order) {
        pname += "." + c->name();
        hosted.push_back(c->name());
    }
    // A process of observers only (the live bridge in the distributed layout) takes the CPU time the run leaves idle,
    // before its DDS threads start (they inherit the value): nobody waits for it (dds/process/process_priority.hpp).
    const bool observers_only =
        std::all_of(raw.begin(), raw.end(), [](const Component* c) { return hosted_as_observer(*c); });
    if (observers_only && rc.observer_nice > 0) {
        const std::string who = join_topics(hosted);
        if (const std::string p = lower_cpu_priority(rc.observer_nice); p.empty())
            spdlog::info("{}: only observers in this process: CPU priority nice {} (run.observer_nice)", who,
                         rc.observer_nice);
        else
            spdlog::warn("{}: CPU priority unchanged ({}); the observers compete with the run", who, p);
    }
    dds = std::make_unique<DdsContext>(rc.domain_id, rc.dds_profile, pname, rc.security_dir,
                                       security::process_identity(hosted));
    tick_reader = dds->reader(topics::kTick, message_ops<msg::Tick>(), kControlReaderProfile);
    control_reader = dds->reader(topics::kRunControl, message_ops<msg::RunControl>(), kLatchedReaderProfile);
    // Only the clock's statuses (its heartbeat): the other members' are for the clock (dds/filters/status_filter.hpp).
    status_reader = dds->status_reader(topics::kStatus, message_ops<msg::ComponentStatus>(), kControlReaderProfile,
                                       kClockName);
    done_writer = dds->writer(topics::kStepDone, message_ops<msg::StepDone>(), kControlWriterProfile);
    status_writer = dds->writer(topics::kStatus, message_ops<msg::ComponentStatus>(), kControlWriterProfile);
    const bool secure = !rc.security_dir.empty();  // no mirrors for observers then (dds/host/mirror.hpp)
    for (Component* c : g.order) {
        Local l;
        l.comp = c;
        l.awaiting_rejoin = opt.rejoin;
        l.observer = hosted_as_observer(*c);
        for (InputBase* in : c->inputs()) {
            auto ch = std::make_unique<Channel>();
            ch->port = in;
            ch->ops = &in->ops();
            // An observer's input that may read a mirror waits for the member table (make_deferred_readers).
            ch->deferred = l.observer && may_read_mirror(in->stride(), secure);
            if (!ch->deferred) ch->reader = topic_reader(*ch, l.observer);
            ch->scratch = ch->ops->create();
            ch->latest = ch->ops->create();
            for (auto& s : ch->slot) s = ch->ops->create();
            l.inputs.push_back(ch.get());
            channels.push_back(std::move(ch));
        }
        for (OutputBase* o : c->outputs()) {
            l.outputs.push_back(host::make_output(o, dds->writer(o->topic(), o->ops(), kDataWriterProfile)));
            if (!secure)
                host::add_mirror(l.outputs.back(), dds->writer(mirror_topic(o->topic()), o->ops(), kDataWriterProfile));
        }
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

// The reader of an input on its topic itself (with the input's stride filter; best-effort for an observer).
DataReader* DdsHost::Impl::topic_reader(const Channel& ch, bool observer) {
    return dds->reader(ch.port->topic(), *ch.ops, kDataReaderProfile, ch.port->stride(), observer);
}

std::vector<DataReader*> DdsHost::Impl::data_readers() {
    std::vector<DataReader*> v{tick_reader};
    for (auto& c : channels)
        if (c->reader != nullptr) v.push_back(c->reader);
    return v;
}

// New Tick or data sample (listener threads, and the main loop after its own work).
void DdsHost::Impl::pump() {
    pending.store(true);
    while (pending.load()) {
        if (!mtx.try_lock()) return;  // the holder sees `pending` before it leaves
        pending.store(false);
        if (!closing) process_data(steady_now_s());
        mtx.unlock();
    }
}

void DdsHost::Impl::process_data(double now) {
    read_ticks(now);
    for (auto& l : locals)
        for (Channel* ch : l.inputs) read_data(l, *ch);
    if (in_advance) return;
    in_advance = true;
    while (advance()) {
    }
    in_advance = false;
}

int DdsHost::Impl::loop() {
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
    // STOP came after every barrier member's last StepDone, so the samples of the last steps are here: an observer,
    // which nobody waited for, computes what it still can before it finishes.
    if (code == kExitOk) process_data(steady_now_s());
    closing = true;
    lock.unlock();
    for (DataReader* r : data_readers()) r->set_listener(nullptr);
    lock.lock();
    for (auto& l : locals) {
        if (code != kExitOk) send_status(l, msg::STATUS_EXIT, "exit code " + std::to_string(code));
        if (!l.killed) l.comp->finish(code == kExitOk);
    }
    report_lateness();
    report_observers();
    return code;
}

DdsHost::DdsHost(const RunConfig& rc, std::vector<std::unique_ptr<Component>> members, HostOptions opt)
    : impl_(std::make_unique<Impl>(rc, std::move(members), opt)) {
    impl_->setup();
}

DdsHost::~DdsHost() = default;

int DdsHost::run() { return impl_->loop(); }

}  // namespace gdnav::runtime
