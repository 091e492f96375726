#include "dds/host/host_control.hpp"

#include <algorithm>

#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <spdlog/spdlog.h>

#include "dds/process/process_priority.hpp"
#include "framework/graph.hpp"

namespace gdnav::runtime::host {

using namespace eprosima::fastdds::dds;

ControlPlane::ControlPlane(const RunConfig& rc, bool rejoin)
    : rc_(rc),
      rejoin_(rejoin),
      timing_{rc.info, rc.window_steps, rc.done_every(), rc.member_timeout_s},
      announce_timeout_s_(rc.startup_timeout_s + (rc.external.empty() ? 0.0 : rc.join_timeout_s)),
      pulse_(&ControlPlane::pulse_loop, this) {}

void ControlPlane::open(DdsContext& dds) {
    tick_reader_ = dds.reader(topics::kTick, message_ops<msg::Tick>(), kControlReaderProfile);
    control_reader_ = dds.reader(topics::kRunControl, message_ops<msg::RunControl>(), kLatchedReaderProfile);
    // Only the clock's statuses (its heartbeat): the other members' are for the clock (dds/filters/status_filter.hpp).
    status_reader_ = dds.status_reader(topics::kStatus, message_ops<msg::ComponentStatus>(), kControlReaderProfile,
                                       kClockName);
    done_writer_ = dds.writer(topics::kStepDone, message_ops<msg::StepDone>(), kControlWriterProfile);
    status_writer_ = dds.writer(topics::kStatus, message_ops<msg::ComponentStatus>(), kControlWriterProfile);
    for (DataReader* r : {control_reader_, status_reader_}) {
        StatusCondition& cond = r->get_statuscondition();
        cond.set_enabled_statuses(StatusMask::data_available());
        waitset_.attach_condition(cond);
    }
}

void ControlPlane::wait(ConditionSeq& active, const eprosima::fastrtps::Duration_t& slice) {
    waitset_.wait(active, slice);
}

void ControlPlane::fill_status(const Local& l, msg::StatusKind kind, const std::string& message,
                               msg::ComponentStatus& out) const {
    const RunInfo& ri = timing_.ri;
    out.run_id(ri.run_index);
    out.step(l.next_step == 0 ? 0 : l.next_step - 1);
    out.t_s(ri.time_of(out.step()));
    out.member(l.comp->name());
    out.host(host_id_);
    out.kind(kind);
    out.inputs(join_topics(input_topics(*l.comp)));
    out.outputs(join_topics(output_topics(*l.comp)));
    out.free_running(!l.barrier);  // an observer: no outputs and not in the barrier (docs/protocol.md)
    out.message(message);
    out.protocol_version(msg::LOCKSTEP_PROTOCOL_VERSION);
    out.faults_version(faults_version_);
    out.run_token(token_);
}

void ControlPlane::send_status(const Local& l, msg::StatusKind kind, const std::string& message) {
    fill_status(l, kind, message, status_out_);
    status_writer_->write(&status_out_);
}

void ControlPlane::flush_statuses() { status_writer_->wait_for_acknowledgments(eprosima::fastrtps::Duration_t(1, 0)); }

void ControlPlane::send_done(const Local& l, std::uint64_t k) {
    done_.run_id(timing_.ri.run_index);
    done_.step(k);
    done_.member_index(l.index);
    done_.run_token(token_);
    done_writer_->write(&done_);
}

void ControlPlane::heartbeat(double now, const std::vector<Local>& locals) {
    if (now < next_heartbeat_s_) return;
    next_heartbeat_s_ = now + kHeartbeatPeriodS;
    const auto kind = phase_ == Phase::Ready ? msg::STATUS_READY : msg::STATUS_HEARTBEAT;
    // A rejoining member asks for its step once it is matched with the run's other members.
    const bool matched = phase_ != Phase::Announce && phase_ != Phase::Matching;
    // Filled in place: the pulse repeats exactly these samples, and their strings keep their storage.
    const std::lock_guard<std::mutex> lock(beat_mtx_);
    beat_.resize(locals.size());
    for (std::size_t i = 0; i < locals.size(); ++i) {
        const Local& l = locals[i];
        fill_status(l, kind, l.awaiting_rejoin && matched ? "rejoin" : rejected_note(l), beat_[i]);
        status_writer_->write(&beat_[i]);
    }
    beat_sent_s_ = now;
}

void ControlPlane::pulse_loop() {
    const auto period = std::chrono::duration<double>(kHeartbeatPeriodS);
    std::unique_lock<std::mutex> lock(beat_mtx_);
    pulse_tid_ = current_tid();
    pulse_cv_.notify_all();
    while (!pulse_stop_) {
        pulse_cv_.wait_for(lock, period);
        if (pulse_stop_) break;
        // Only when the main loop is late: while it runs, its own heartbeats carry the current step.
        const double now = steady_now_s();
        if (beat_.empty() || now - beat_sent_s_ < 1.5 * kHeartbeatPeriodS) continue;
        for (msg::ComponentStatus& s : beat_) status_writer_->write(&s);
        beat_sent_s_ = now;
    }
}

int ControlPlane::pulse_tid() {
    std::unique_lock<std::mutex> lock(beat_mtx_);
    pulse_cv_.wait(lock, [this] { return pulse_tid_ != 0 || pulse_stop_; });
    return pulse_tid_;
}

void ControlPlane::stop_pulse() {
    {
        const std::lock_guard<std::mutex> lock(beat_mtx_);
        pulse_stop_ = true;
    }
    pulse_cv_.notify_all();
    if (pulse_.joinable()) pulse_.join();
}

ControlPlane::~ControlPlane() { stop_pulse(); }

bool ControlPlane::read_control(int& code, ControlHandler& handler) {
    SampleInfo info;
    while (control_reader_->take_next_sample(&control_, &info) == ReturnCode_t::RETCODE_OK) {
        if (!info.valid_data || control_.run_id() != timing_.ri.run_index || !ours(control_)) continue;
        switch (control_.command()) {
            case msg::RUN_CONFIGURE:
            case msg::RUN_FAULTS:
                if (phase_ != Phase::Announce && control_.command() == msg::RUN_FAULTS &&
                    control_.faults_version() > faults_version_) {
                    if (!handler.live_faults(control_)) {
                        code = kExitStartup;
                        return false;
                    }
                    faults_version_ = control_.faults_version();
                    next_heartbeat_s_ = 0.0;  // acknowledge at once (the clock holds the run until every member has)
                }
                if (phase_ != Phase::Announce) break;
                // A rejoining member may see only FAULTS samples (they carry the table as well).
                if (control_.command() == msg::RUN_FAULTS && !rejoin_) break;
                if (!configure(code, handler)) return false;
                break;
            case msg::RUN_STOP:
                spdlog::debug("host {}: STOP received", host_id_);
                code = kExitOk;
                return false;
            case msg::RUN_ABORT:
                // The clock logs the reason and the launcher's last line repeats it: each member's copy only at
                // debug level (an external member's owner gets it from DdsHost::abort_reason()).
                abort_reason_ = control_.reason().to_string();
                spdlog::debug("run aborted by the clock: {}", abort_reason_);
                code = kExitAborted;
                return false;
            default:
                break;
        }
    }
    return true;
}

bool ControlPlane::ours(const msg::RunControl& c) {
    if (token_ != 0 && c.run_token() != token_) {
        foreign_.note(c.run_token(), "a RunControl writer", "RunControl");
        return false;
    }
    return true;
}

bool ControlPlane::configure(int& code, ControlHandler& handler) {
    if (control_.protocol_version() != msg::LOCKSTEP_PROTOCOL_VERSION) {
        spdlog::error("the clock speaks lockstep protocol version {}, this member speaks {}; "
                      "cannot join (docs/protocol.md, 'Versioning')",
                      control_.protocol_version(), msg::LOCKSTEP_PROTOCOL_VERSION);
        code = kExitStartup;
        return false;
    }
    adopt_timing();
    token_ = control_.run_token();
    table_.assign(control_.members().begin(), control_.members().end());
    if (!handler.configure(control_)) {
        code = kExitStartup;
        return false;
    }
    faults_version_ = control_.faults_version();
    phase_ = Phase::Matching;
    // The clock is alive now: a member started long before it must not count that wait as silence.
    last_clock_s_ = steady_now_s();
    return true;
}

void ControlPlane::adopt_timing() {
    RunInfo& ri = timing_.ri;
    if (control_.steps() != ri.steps || control_.dt_s() != ri.dt_s || control_.t0_s() != ri.t0_s)
        spdlog::debug("timing from the clock: {} steps of {} s from t0 = {} s", control_.steps(), control_.dt_s(),
                      control_.t0_s());
    ri.steps = control_.steps();
    ri.dt_s = control_.dt_s();
    ri.t0_s = control_.t0_s();
    timing_.window_steps = control_.window_steps();
    ri.seed = control_.seed();
    timing_.done_every = std::max<std::uint64_t>(control_.done_every(), 1);
    timing_.member_timeout_s = control_.member_timeout_s();
}

bool ControlPlane::read_ticks(double now) {
    bool more_dead = false;
    SampleInfo info;
    while (tick_reader_->take_next_sample(&tick_, &info) == ReturnCode_t::RETCODE_OK) {
        if (!info.valid_data || tick_.stamp().run_id() != timing_.ri.run_index) continue;
        if (tick_.run_token() != token_) {  // another run's, or (token 0) before this host has joined
            if (token_ != 0) foreign_.note(tick_.run_token(), "a Tick writer", "Tick");
            continue;
        }
        last_clock_s_ = now;
        if (!have_tick_ || tick_.stamp().step() > tick_step_) tick_step_ = tick_.stamp().step();
        have_tick_ = true;
        if (phase_ == Phase::Ready) phase_ = Phase::Running;  // a rejoining member sees Ticks while matching
        const std::uint64_t dead = tick_.dead_mask() & ~revived_mask_;
        if ((dead | dead_mask_) != dead_mask_) {
            dead_mask_ |= dead;
            more_dead = true;
        }
    }
    return more_dead;
}

void ControlPlane::read_status(double now) {
    SampleInfo info;
    while (status_reader_->take_next_sample(&status_in_, &info) == ReturnCode_t::RETCODE_OK) {
        if (!info.valid_data || status_in_.member().to_string() != kClockName ||
            status_in_.run_id() != timing_.ri.run_index || token_ == 0)
            continue;
        if (status_in_.run_token() == token_)
            last_clock_s_ = now;
        else
            foreign_.note(status_in_.run_token(), "clock " + status_in_.host().to_string(), "its heartbeat");
    }
}

void ControlPlane::matched_all() {
    phase_ = Phase::Ready;
    next_heartbeat_s_ = 0.0;  // report READY at once
}

bool ControlPlane::clock_matched() const {
    SubscriptionMatchedStatus ts;
    tick_reader_->get_subscription_matched_status(ts);
    PublicationMatchedStatus ds;
    done_writer_->get_publication_matched_status(ds);
    return ts.current_count >= 1 && ds.current_count >= 1;
}

void ControlPlane::start(double now) {
    start_s_ = now;
    last_clock_s_ = now;
}

bool ControlPlane::clock_alive(double now, int& code) const {
    const double silent_s = now - last_clock_s_;
    if (phase_ == Phase::Announce || (phase_ != Phase::Running && !have_tick_)) {
        if (phase_ == Phase::Announce && now - start_s_ > announce_timeout_s_) {
            spdlog::error("no clock: no member table from the clock '{}' within {:.1f} s", kClockName,
                          announce_timeout_s_);
            code = kExitStartup;
            return false;
        }
        if (phase_ != Phase::Announce && silent_s > timing_.member_timeout_s) {
            spdlog::error("lost the clock '{}': no Tick or heartbeat for {:.1f} s before the start", kClockName,
                          silent_s);
            code = kExitLostClock;
            return false;
        }
    } else if (silent_s > timing_.member_timeout_s) {
        spdlog::error("lost the clock '{}': no Tick or heartbeat for {:.1f} s (last Tick: step {})", kClockName,
                      silent_s, tick_step_);
        code = kExitLostClock;
        return false;
    }
    return true;
}

std::uint32_t ControlPlane::index_of(const std::string& name) const {
    std::uint32_t index = UINT32_MAX;
    for (std::uint32_t i = 0; i < table_.size(); ++i)
        if (table_[i].name().to_string() == name) index = i;
    return index;
}

int ControlPlane::readers_of(const std::string& topic) const {
    int n = 0;
    for (const auto& m : table_)
        for (const auto& t : split_topics(m.inputs().to_string())) n += (t == topic);
    return n;
}

std::vector<std::string> ControlPlane::names(const std::vector<std::uint32_t>& indices) const {
    std::vector<std::string> v;
    for (auto i : indices) v.push_back(table_[i].name().to_string());
    return v;
}

void ControlPlane::revive(std::uint32_t i) {
    revived_mask_ |= 1ULL << i;
    dead_mask_ &= ~(1ULL << i);
}

}  // namespace gdnav::runtime::host
