#pragma once
// The DDS host's control plane (docs/protocol.md §3): the clock's RunControl (CONFIGURE, FAULTS, STOP, ABORT), its
// Ticks and heartbeats, the host's own ComponentStatus and StepDone, the member table and the host's phase.
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <fastdds/dds/core/condition/WaitSet.hpp>

#include "dds/dds_context.hpp"
#include "dds/foreign_runs.hpp"
#include "dds/host/host_inbox.hpp"
#include "framework/lockstep.hpp"
#include "framework/run_config.hpp"
#include "msgs/messages.hpp"

namespace gdnav::runtime::host {

// The run's timing: from the local config, replaced by the clock's CONFIGURE (protocol version >= 1), so a member
// that knows only the domain and the run id (an external client) steps exactly like a built-in one.
struct RunTiming {
    RunInfo ri;
    std::uint64_t window_steps{0};
    std::uint64_t done_every{1};
    double member_timeout_s{0.0};
};

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
    enum class Phase { Announce, Matching, Ready, Running };

    ControlPlane(const RunConfig& rc, bool rejoin);
    ~ControlPlane();
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
    // Ticks. Returns true when the clock declared another producer dead (dead_mask() grew).
    bool read_ticks(double now);

    // Matching is done (the host's readers and writers too): READY at once.
    void matched_all();
    // Whether the Tick reader and the StepDone writer are matched with the clock.
    [[nodiscard]] bool clock_matched() const;
    // Starts the clock's silence timer (the main loop's start).
    void start(double now);
    // The pulse thread (see heartbeat) starts with the control plane, before the host lowers its process's CPU
    // priority, which spares it (pulse_tid). stop_pulse ends it: when the main loop ends, before the last statuses
    // and before DDS is torn down.
    [[nodiscard]] int pulse_tid();
    void stop_pulse();
    // The host's loop was not scheduled for `stall_s` (own_stall_s): that time is not the clock's silence.
    void discount_own_stall(double stall_s) { last_clock_s_ += stall_s; }
    // False when the clock is missing or lost (then `code` is the exit code).
    bool clock_alive(double now, int& code) const;

    // The members' heartbeats, every kHeartbeatPeriodS. A pulse thread repeats the last ones while the main loop
    // is held up (a long step, a write that blocks on the disk): a heartbeat says the process is alive, and a member
    // that is alive but makes no progress is the clock's stall_timeout_s to judge, not member_timeout_s.
    void heartbeat(double now, const std::vector<Local>& locals);
    void send_status(const Local& l, msg::StatusKind kind, const std::string& message);
    // Waits, at most 1 s, until the clock has acknowledged the statuses sent: a member's last status (its error or
    // exit code) must reach the clock before the process ends, or the clock only sees its heartbeats stop.
    void flush_statuses();
    void send_done(const Local& l, std::uint64_t k);

    [[nodiscard]] Phase phase() const { return phase_; }
    [[nodiscard]] const RunTiming& timing() const { return timing_; }
    [[nodiscard]] const std::string& host_id() const { return host_id_; }
    // The run token of the CONFIGURE the host joined with (0 before); control messages of another are ignored.
    [[nodiscard]] std::uint64_t token() const { return token_; }
    // Control messages of other runs ignored: one line at the end, when there were any.
    void report_foreign() const { foreign_.report(); }
    // Whether step k may be computed now: Ticks have started, k is within the window and within the run.
    [[nodiscard]] bool may_step(std::uint64_t k) const {
        return have_tick_ && k <= tick_step_ + timing_.window_steps && k < timing_.ri.steps;
    }

    // The clock's member table (CONFIGURE): index of `name`, UINT32_MAX when absent.
    [[nodiscard]] const std::vector<msg::MemberInfo>& table() const { return table_; }
    [[nodiscard]] std::uint32_t index_of(const std::string& name) const;
    // Readers of `topic` the member table announces.
    [[nodiscard]] int readers_of(const std::string& topic) const;
    // The names of the members at `indices` of the table.
    [[nodiscard]] std::vector<std::string> names(const std::vector<std::uint32_t>& indices) const;

    // Producers the clock declared dead (bit = table index), less those that rejoined.
    [[nodiscard]] std::uint64_t dead_mask() const { return dead_mask_; }
    // Member i came back: its old dead bit no longer counts.
    void revive(std::uint32_t i);
    // The reason of the clock's ABORT ("" when none came).
    [[nodiscard]] const std::string& abort_reason() const { return abort_reason_; }

private:
    bool configure(int& code, ControlHandler& handler);
    void fill_status(const Local& l, msg::StatusKind kind, const std::string& message, msg::ComponentStatus& out) const;
    void pulse_loop();
    // Whether a RunControl sample is this run's: before joining, any CONFIGURE (the first one is joined), STOP or
    // ABORT of the run id; afterwards only those of the run token.
    bool ours(const msg::RunControl& c);
    void adopt_timing();

    const RunConfig& rc_;
    bool rejoin_{false};
    RunTiming timing_;
    // How long to wait for the member table: start-up, plus the join time of external members.
    double announce_timeout_s_{0.0};
    std::uint32_t faults_version_{0};  // the fault schedule adopted (acknowledged in every status)

    eprosima::fastdds::dds::DataReader* tick_reader_{nullptr};
    eprosima::fastdds::dds::DataReader* control_reader_{nullptr};
    eprosima::fastdds::dds::DataReader* status_reader_{nullptr};
    eprosima::fastdds::dds::DataWriter* done_writer_{nullptr};
    eprosima::fastdds::dds::DataWriter* status_writer_{nullptr};
    eprosima::fastdds::dds::WaitSet waitset_;

    Phase phase_{Phase::Announce};
    std::vector<msg::MemberInfo> table_;
    std::uint64_t tick_step_{0};
    bool have_tick_{false};
    std::uint64_t dead_mask_{0};
    std::uint64_t revived_mask_{0};  // members that rejoined: their old dead bit no longer counts
    double last_clock_s_{0.0};
    double start_s_{0.0};
    double next_heartbeat_s_{0.0};
    std::string host_id_{host_identity()};
    std::string abort_reason_;
    std::uint64_t token_{0};
    ForeignRuns foreign_;

    msg::Tick tick_;
    msg::RunControl control_;
    msg::ComponentStatus status_in_;
    msg::ComponentStatus status_out_;
    msg::StepDone done_;

    // The pulse: the heartbeats the main loop sent last, and when (steady seconds); both under beat_mtx_.
    std::mutex beat_mtx_;
    std::condition_variable pulse_cv_;
    std::vector<msg::ComponentStatus> beat_;
    double beat_sent_s_{0.0};
    bool pulse_stop_{false};
    int pulse_tid_{0};
    std::thread pulse_;
};

}  // namespace gdnav::runtime::host
