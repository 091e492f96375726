#include "dds/host/host_control.hpp"

#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <spdlog/spdlog.h>

#include "framework/graph.hpp"

namespace gdnav::dds::host {

using namespace eprosima::fastdds::dds;

ControlPlane::ControlPlane(const framework::RunConfig& rc, bool rejoin) : rejoin_(rejoin), run_(rc) {}

void ControlPlane::open(DdsContext& dds) {
    tick_reader_ = dds.reader(topics::kTick, msg::message_ops<msg::Tick>(), kControlReaderProfile);
    control_reader_ = dds.reader(topics::kRunControl, msg::message_ops<msg::RunControl>(), kLatchedReaderProfile);
    // Only the clock's statuses (its heartbeat): the other members' are for the clock (dds/filters/status_filter.hpp).
    status_reader_ = dds.status_reader(topics::kStatus, msg::message_ops<msg::ComponentStatus>(), kControlReaderProfile,
                                       framework::kClockName);
    done_writer_ = dds.writer(topics::kStepDone, msg::message_ops<msg::StepDone>(), kMemberControlWriterProfile,
                              kControlWriterProfile);
    status_writer_ = dds.writer(topics::kStatus, msg::message_ops<msg::ComponentStatus>(),
                                kMemberControlWriterProfile, kControlWriterProfile);
    pulse_.attach(status_writer_);
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
    const framework::RunInfo& ri = run_.timing().ri;
    out.run_id(ri.run_index);
    out.step(l.next_step == 0 ? 0 : l.next_step - 1);
    out.t_s(ri.time_of(out.step()));
    out.member(l.comp->name());
    out.host(host_id_);
    out.kind(kind);
    out.inputs(framework::join_topics(framework::input_topics(*l.comp)));
    out.outputs(framework::join_topics(framework::output_topics(*l.comp)));
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
    done_.run_id(run_.timing().ri.run_index);
    done_.step(k);
    done_.member_index(l.index);
    done_.run_token(token_);
    done_writer_->write(&done_);
}

void ControlPlane::heartbeat(double now, const std::vector<Local>& locals) {
    if (!pulse_.due(now)) return;
    using Phase = RunPhase::Phase;
    const Phase phase = run_.phase();
    const auto kind = phase == Phase::Ready ? msg::STATUS_READY : msg::STATUS_HEARTBEAT;
    // A rejoining member asks for its step once it is matched with the run's other members.
    const bool matched = phase != Phase::Announce && phase != Phase::Matching;
    pulse_.send(now, locals.size(), [&](std::size_t i, msg::ComponentStatus& out) {
        const Local& l = locals[i];
        fill_status(l, kind, l.awaiting_rejoin && matched ? "rejoin" : rejected_note(l), out);
    });
}

bool ControlPlane::read_control(int& code, ControlHandler& handler) {
    SampleInfo info;
    while (control_reader_->take_next_sample(&control_, &info) == ReturnCode_t::RETCODE_OK) {
        if (!info.valid_data || control_.run_id() != run_.timing().ri.run_index || !ours(control_)) continue;
        switch (control_.command()) {
            case msg::RUN_CONFIGURE:
            case msg::RUN_FAULTS:
                if (run_.phase() != RunPhase::Phase::Announce && control_.command() == msg::RUN_FAULTS &&
                    control_.faults_version() > faults_version_) {
                    if (!handler.live_faults(control_)) {
                        code = framework::kExitStartup;
                        return false;
                    }
                    faults_version_ = control_.faults_version();
                    pulse_.hurry();  // acknowledge at once (the clock holds the run until every member has)
                }
                if (run_.phase() != RunPhase::Phase::Announce) break;
                // A rejoining member may see only FAULTS samples (they carry the table as well).
                if (control_.command() == msg::RUN_FAULTS && !rejoin_) break;
                if (!configure(code, handler)) return false;
                break;
            case msg::RUN_STOP:
                spdlog::debug("host {}: STOP received", host_id_);
                code = framework::kExitOk;
                return false;
            case msg::RUN_ABORT:
                // The clock logs the reason and the launcher's last line repeats it: each member's copy only at
                // debug level (an external member's owner gets it from DdsHost::abort_reason()).
                abort_reason_ = control_.reason().to_string();
                spdlog::debug("run aborted by the clock: {}", abort_reason_);
                code = framework::kExitAborted;
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
        code = framework::kExitStartup;
        return false;
    }
    run_.adopt_timing(control_);
    token_ = control_.run_token();
    members_.adopt(control_.members());
    if (!handler.configure(control_)) {
        code = framework::kExitStartup;
        return false;
    }
    faults_version_ = control_.faults_version();
    run_.joined(framework::steady_now_s());
    return true;
}

bool ControlPlane::read_ticks(double now) {
    bool more_dead = false;
    SampleInfo info;
    while (tick_reader_->take_next_sample(&tick_, &info) == ReturnCode_t::RETCODE_OK) {
        if (!info.valid_data || tick_.stamp().run_id() != run_.timing().ri.run_index) continue;
        if (tick_.run_token() != token_) {  // another run's, or (token 0) before this host has joined
            if (token_ != 0) foreign_.note(tick_.run_token(), "a Tick writer", "Tick");
            continue;
        }
        run_.tick(tick_.stamp().step(), now);
        if (members_.declare_dead(tick_.dead_mask())) more_dead = true;
    }
    return more_dead;
}

void ControlPlane::read_status(double now) {
    SampleInfo info;
    while (status_reader_->take_next_sample(&status_in_, &info) == ReturnCode_t::RETCODE_OK) {
        if (!info.valid_data || status_in_.member().to_string() != framework::kClockName ||
            status_in_.run_id() != run_.timing().ri.run_index || token_ == 0)
            continue;
        if (status_in_.run_token() == token_)
            run_.heard_clock(now);
        else
            foreign_.note(status_in_.run_token(), "clock " + status_in_.host().to_string(), "its heartbeat");
    }
}

void ControlPlane::matched_all() {
    run_.matched();
    pulse_.hurry();  // report READY at once
}

bool ControlPlane::clock_matched() const {
    SubscriptionMatchedStatus ts;
    tick_reader_->get_subscription_matched_status(ts);
    PublicationMatchedStatus ds;
    done_writer_->get_publication_matched_status(ds);
    return ts.current_count >= 1 && ds.current_count >= 1;
}

}  // namespace gdnav::dds::host
