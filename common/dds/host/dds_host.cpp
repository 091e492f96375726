// The DDS host: set-up, the main loop and the listener pump (the parts: host_impl.hpp).
#include "dds/host/host_impl.hpp"

#include <algorithm>

#include <spdlog/spdlog.h>

#include "files/write_error.hpp"

#include "dds/host/mirror.hpp"
#include "dds/process/run_cause.hpp"
#include "dds/process/process_priority.hpp"
#include "dds/process/process_signals.hpp"
#include "dds/security/security.hpp"
#include "framework/graph.hpp"

namespace gdnav::dds {

namespace {
constexpr int kExitStepFailed = 1;  // "internal error" (docs/protocol.md §5): a member's step threw
}  // namespace

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::Duration_t;

void DdsHost::Impl::setup() {
    std::vector<framework::Component*> raw;
    for (auto& c : owned) raw.push_back(c.get());
    const framework::Graph g = framework::build_graph(raw);  // local step order (zero-lag edges inside this process)
    std::string pname = "gdnav";
    std::vector<std::string> hosted;
    for (auto* c : g.order) {
        pname += "." + c->name();
        hosted.push_back(c->name());
    }
    // A process of observers only (the live bridge in the distributed layout) takes the CPU time the run leaves idle,
    // before its DDS threads start (they inherit the value): nobody waits for it (dds/process/process_priority.hpp).
    const bool observers_only =
        std::all_of(raw.begin(), raw.end(), [](const framework::Component* c) { return host::hosted_as_observer(*c); });
    if (observers_only && rc.observer_nice > 0) {
        const std::string who = framework::join_topics(hosted);
        if (const std::string p = lower_cpu_priority(rc.observer_nice, control.pulse().tid()); p.empty())
            spdlog::info("{}: only observers in this process: CPU priority nice {} (run.observer_nice)", who,
                         rc.observer_nice);
        else
            spdlog::warn("{}: CPU priority unchanged ({}); the observers compete with the run", who, p);
    }
    dds = std::make_unique<DdsContext>(rc.domain_id, rc.dds_profile, pname, rc.security_dir,
                                       security::process_identity(hosted), hosted);
    // The members gdnav starts announce themselves (dds/participants.hpp); an external one may be another vendor's.
    inputs.identify(&dds->participants(), [this](const std::string& name) {
        return !rc.is_external(name) && std::any_of(rc.members.begin(), rc.members.end(),
                                                    [&](const framework::MemberSpec& m) { return m.name == name; });
    });
    control.open(*dds);
    for (framework::Component* c : g.order) locals.push_back(make_local(c));
    host::route_locally(locals);
}

host::Local DdsHost::Impl::make_local(framework::Component* c) {
    host::Local l;
    l.comp = c;
    l.awaiting_rejoin = opt.rejoin;
    l.observer = host::hosted_as_observer(*c);
    l.barrier = !opt.free_running && !l.observer;
    for (framework::InputBase* in : c->inputs()) {
        host::Channel* ch = inputs.add(in);
        // An observer's input that may read a mirror waits for the member table (Observers::make_readers).
        if (observers.defers(l, *in))
            ch->defer_reader();
        else
            ch->set_reader(host::topic_reader(*dds, *ch, l.observer));
        l.inputs.push_back(ch);
    }
    for (framework::OutputBase* o : c->outputs()) {
        l.outputs.push_back(host::make_output(o, dds->writer(o->topic(), o->ops(), kDataWriterProfile)));
        if (observers.mirrors())
            host::add_mirror(l.outputs.back(), dds->writer(mirror_topic(o->topic()), o->ops(), kDataWriterProfile));
    }
    return l;
}

std::vector<DataReader*> DdsHost::Impl::data_readers() const {
    std::vector<DataReader*> v{control.tick_reader()};
    for (DataReader* r : inputs.readers()) v.push_back(r);
    return v;
}

void DdsHost::Impl::pump() {
    pending.store(true);
    while (pending.load()) {
        if (!mtx.try_lock()) return;  // the holder sees `pending` before it leaves
        pending.store(false);
        if (!closing) process_data(framework::steady_now_s(), false);
        mtx.unlock();
    }
}

void DdsHost::Impl::process_data(double now, bool all) {
    if ((tick_fresh.exchange(false) || all) && control.read_ticks(now))
        inputs.apply_dead_mask(control.members().dead_mask());
    const framework::RunInfo& ri = control.run().timing().ri;
    for (auto& l : locals)
        for (host::Channel* ch : l.inputs)
            if (ch->take_fresh() || all) inputs.read(l, *ch, ri);
    if (in_advance) return;
    in_advance = true;
    while (advance()) {
    }
    in_advance = false;
}

bool DdsHost::Impl::tick_over(int& code) {
    const double now = framework::steady_now_s();
    if (stop_requested()) {
        spdlog::warn("host {}: stopped by signal {}", control.host_id(), stop_signal());
        code = framework::kExitInterrupted;
        return false;
    }
    if (!step_error.empty()) {
        code = step_write_failed ? framework::kExitWriteFailed : kExitStepFailed;
        spdlog::error("{}; leaving the run (exit code {})", step_error, code);
        tell_launcher(step_error);
        return false;
    }
    if (const double stall = last_loop_s > 0.0 ? framework::own_stall_s(now - last_loop_s) : 0.0; stall > 0.0) {
        control.run().discount_own_stall(stall);
        spdlog::debug("host {}: not scheduled for {:.2f} s; the clock's silence meanwhile is not counted",
                      control.host_id(), stall);
    }
    last_loop_s = now;
    if (!control.read_control(code, *this)) return false;
    if (not_in_table) {
        code = framework::kExitStartup;
        return false;
    }
    control.read_status(now);
    if (control.run().phase() == host::RunPhase::Phase::Matching && all_matched()) control.matched_all();
    control.heartbeat(now, locals);
    pending.store(false);
    process_data(now, true);
    return control.run().clock_alive(now, code);
}

int DdsHost::Impl::loop() {
    control.run().start(framework::steady_now_s());
    ConditionSeq active;
    const Duration_t slice(0, static_cast<std::uint32_t>(framework::kWaitSliceS * 1e9));
    int code = framework::kExitOk;
    control.tick_reader()->set_listener(listen(&tick_fresh), StatusMask::data_available());
    for (auto& l : locals)
        for (host::Channel* ch : l.inputs)
            if (ch->reader() != nullptr)
                ch->reader()->set_listener(listen(ch->fresh_flag()), StatusMask::data_available());
    std::unique_lock<std::recursive_mutex> lock(mtx, std::defer_lock);
    while (true) {
        control.wait(active, slice);
        lock.lock();
        if (!tick_over(code)) break;
        lock.unlock();
        pump();
    }
    control.pulse().stop();
    // STOP came after every barrier member's last StepDone, so the samples of the last steps are here: an observer,
    // which nobody waited for, computes what it still can before it finishes.
    if (code == framework::kExitOk) process_data(framework::steady_now_s(), true);
    closing = true;
    lock.unlock();
    for (DataReader* r : data_readers()) r->set_listener(nullptr);
    lock.lock();
    const int finish_code = finish(code);
    return code == framework::kExitOk ? finish_code : code;
}

int DdsHost::Impl::finish(int code) {
    int finish_code = framework::kExitOk;
    for (auto& l : locals) {
        if (!step_error.empty())
            control.send_status(l, msg::STATUS_ERROR, step_error);  // the clock's reason names the cause
        else if (code != framework::kExitOk)
            control.send_status(l, msg::STATUS_EXIT, "exit code " + std::to_string(code));
        if (l.killed) continue;
        // Every member finishes (closes its files) even when another one's finish fails; the first failure is the
        // process's exit code (6 for a file it could not write, docs/runtime.md "Exit codes").
        try {
            l.comp->finish(code == framework::kExitOk);
        } catch (const std::exception& e) {
            const std::string line = "member '" + l.comp->name() + "' failed at the end of the run: " + e.what();
            spdlog::error("{}", line);
            tell_launcher(line);
            if (finish_code == framework::kExitOk)
                finish_code =
                    dynamic_cast<const files::WriteError*>(&e) ? framework::kExitWriteFailed : kExitStepFailed;
        }
    }
    if (!step_error.empty() || code != framework::kExitOk) control.flush_statuses();
    control.report_foreign();
    inputs.report_lateness(locals, rc.out_dir);
    host::Inputs::report_rejected(locals);
    host::Observers::report(locals, control.run().timing().ri.steps);
    return finish_code;
}

DdsHost::DdsHost(const framework::RunConfig& rc, std::vector<std::unique_ptr<framework::Component>> members,
                 HostOptions opt)
    : impl_(std::make_unique<Impl>(rc, std::move(members), std::move(opt))) {
    impl_->setup();
}

DdsHost::~DdsHost() = default;

int DdsHost::run() { return impl_->loop(); }

std::string DdsHost::abort_reason() const { return impl_->control.abort_reason(); }

}  // namespace gdnav::dds
