#pragma once
// The DDS host's control plane (docs/protocol.md §3): the control topics (the clock's RunControl: CONFIGURE, FAULTS,
// STOP, ABORT; its Ticks and heartbeats; the host's own ComponentStatus and StepDone), composing what they tell and
// feed: the run's phase and timing (host_phase.hpp), the member table (host_members.hpp) and the heartbeats' pulse
// (host_pulse.hpp).
#include <cstdint>
#include <string>
#include <vector>

#include <fastdds/dds/core/condition/WaitSet.hpp>

#include "dds/compat.hpp"
#include "dds/dds_context.hpp"
#include "dds/foreign_runs.hpp"
#include "dds/host/host_inbox.hpp"
#include "dds/host/host_members.hpp"
#include "dds/host/host_phase.hpp"
#include "dds/host/host_pulse.hpp"
#include "framework/lockstep.hpp"
#include "framework/run_config.hpp"
#include "msgs/messages.hpp"

namespace gdnav::dds::host {

// What the host does when RunControl brings a member table or a longer fault schedule. Each returns false when
// the host cannot go on (a start-up error).
class ControlHandler {
public:
    virtual ~ControlHandler() = default;
    // CONFIGURE (or, for a rejoining member, FAULTS): the timing and the member table are adopted already.
    virtual bool configure(const msg::RunControl& control) = 0;
    // FAULTS with a newer schedule while the host is configured (a fault injected live).
    virtual bool live_faults(const msg::RunControl& control) = 0;
};

class ControlPlane {
public:
    // The pulse thread starts here (host_pulse.hpp).
    ControlPlane(const framework::RunConfig& rc, bool rejoin);
    ControlPlane(const ControlPlane&) = delete;
    ControlPlane& operator=(const ControlPlane&) = delete;

    // The control topics' readers and writers; the waitset wakes on RunControl and ComponentStatus.
    void open(DdsContext& dds);
    void wait(eprosima::fastdds::dds::ConditionSeq& active, const eprosima::fastrtps::Duration_t& slice);
    [[nodiscard]] eprosima::fastdds::dds::DataReader* tick_reader() const { return tick_reader_; }

    // RunControl. Returns false when the run must end; `code` is then the exit code.
    bool read_control(int& code, ControlHandler& handler);
    // The clock's heartbeats (it is alive).
    void read_status(double now);
    // Ticks. Returns true when the clock declared another producer dead (members().dead_mask() grew).
    bool read_ticks(double now);

    // Matching is done (the host's readers and writers too): READY at once.
    void matched_all();
    // Whether the Tick reader and the StepDone writer are matched with the clock.
    [[nodiscard]] bool clock_matched() const;

    // The members' heartbeats, every kHeartbeatPeriodS (repeated by the pulse while the main loop is held up).
    void heartbeat(double now, const std::vector<Local>& locals);
    void send_status(const Local& l, msg::StatusKind kind, const std::string& message);
    // Waits, at most 1 s, until the clock has acknowledged the statuses sent: a member's last status (its error or
    // exit code) must reach the clock before the process ends, or the clock only sees its heartbeats stop.
    void flush_statuses();
    void send_done(const Local& l, std::uint64_t k);

    // The run's phase and timing, the clock's Ticks and silence.
    [[nodiscard]] const RunPhase& run() const { return run_; }
    [[nodiscard]] RunPhase& run() { return run_; }
    // The clock's member table (CONFIGURE) and its dead members.
    [[nodiscard]] const MemberTable& members() const { return members_; }
    [[nodiscard]] MemberTable& members() { return members_; }
    // The heartbeats' pulse thread: its id (a process of observers spares it when it lowers its priority), stop().
    [[nodiscard]] Pulse& pulse() { return pulse_; }

    [[nodiscard]] const std::string& host_id() const { return host_id_; }
    // Control messages of other runs ignored: one line at the end, when there were any.
    void report_foreign() const { foreign_.report(); }
    // The reason of the clock's ABORT ("" when none came).
    [[nodiscard]] const std::string& abort_reason() const { return abort_reason_; }

private:
    bool configure(int& code, ControlHandler& handler);
    void fill_status(const Local& l, msg::StatusKind kind, const std::string& message, msg::ComponentStatus& out) const;
    // Whether a RunControl sample is this run's: before joining, any CONFIGURE (the first one is joined), STOP or
    // ABORT of the run id; afterwards only those of the run token.
    bool ours(const msg::RunControl& c);

    bool rejoin_{false};
    RunPhase run_;
    MemberTable members_;
    std::uint32_t faults_version_{0};  // the fault schedule adopted (acknowledged in every status)
    // The run token of the CONFIGURE the host joined with (0 before); control messages of another are ignored.
    std::uint64_t token_{0};

    eprosima::fastdds::dds::DataReader* tick_reader_{nullptr};
    eprosima::fastdds::dds::DataReader* control_reader_{nullptr};
    eprosima::fastdds::dds::DataReader* status_reader_{nullptr};
    eprosima::fastdds::dds::DataWriter* done_writer_{nullptr};
    eprosima::fastdds::dds::DataWriter* status_writer_{nullptr};
    eprosima::fastdds::dds::WaitSet waitset_;

    std::string host_id_{framework::host_identity()};
    std::string abort_reason_;
    ForeignRuns foreign_;

    msg::Tick tick_;
    msg::RunControl control_;
    msg::ComponentStatus status_in_;
    msg::ComponentStatus status_out_;
    msg::StepDone done_;

    Pulse pulse_;  // last: its thread starts once the members above are made, and stops first
};

}  // namespace gdnav::dds::host
