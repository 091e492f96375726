#pragma once
// The DDS host's state (internal: DdsHost's implementation, split by concern):
//   dds_host.cpp            set-up, the main loop, the listener pump
//   host/host_control.cpp   the clock's control plane: RunControl, Ticks, heartbeats, the member table
//   host/host_step.cpp      inputs by step, stepping the members, publishing, StepDone
//   host/host_faults.cpp    the fault schedule: live faults, kills, restarts, rejoin
#include "dds/host/dds_host.hpp"

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <fastdds/dds/core/condition/WaitSet.hpp>

#include "dds/dds_context.hpp"
#include "framework/faults/input_faults.hpp"
#include "dds/host/host_inbox.hpp"
#include "framework/lockstep.hpp"
#include "msgs/messages.hpp"

namespace gdnav::runtime {

using namespace eprosima::fastdds::dds;

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

    void setup();

    std::vector<DataReader*> data_readers();  // those made so far
    void make_deferred_readers();
    DataReader* topic_reader(const Channel& ch, bool observer);

    // New Tick or data sample (listener threads, and the main loop after its own work).
    void pump();

    void process_data(double now);

    void send_status(const Local& l, msg::StatusKind kind, const std::string& message);

    void heartbeat(double now);

    // Returns false when the run must end; `code` is then the exit code.
    bool read_control(int& code);

    void adopt_timing();

    // The clock's fault schedule (protocol version 2). Returns false when it cannot be read.
    bool adopt_faults();

    // A longer schedule from the clock (a fault injected live): inputs take on the new faults, and the next
    // heartbeat acknowledges the version (the clock holds the run until every member has).
    bool adopt_live_faults();

    // Member f.target, declared dead, came back (gdnav component --rejoin) and computes again from step f.from_step:
    // this host's inputs from it wait for its samples from that step on; or, if it is ours, it starts there.
    void rejoin(const faults::Fault& f);

    void configure_from_table();

    bool all_matched();

    void read_ticks(double now);

    void apply_dead_mask();

    void read_status(double now);

    void read_data(Local& l, Channel& ch);

    static void warn_too_far(const Local& l, const Channel& ch, std::uint64_t s);

    // A local member's output of step k: into the inboxes of the local readers, and on DDS if anyone outside reads it.
    void publish(host::Output& o, std::uint64_t k);

    bool inputs_ready(const Local& l, std::uint64_t k);

    void send_done(const Local& l, std::uint64_t k);

    // Whether the clock waits for member `l` (it reports StepDone): not for a free-running host or an observer.
    [[nodiscard]] bool in_barrier(const Local& l) const { return !opt.free_running && !l.observer; }

    // Observers: the steps they skipped (log lines at the end).
    void report_observers();

    // A restart: member `l` is created anew at step k (the old object goes, with its state).
    void restart(Local& l, std::uint64_t k);

    // A scheduled kill or restart of member `l` at step k (called every step when the run has faults). Returns
    // false when `l` is not stepped at k.
    bool apply_member_faults(Local& l, std::uint64_t k);

    // Free inputs of a step about to run: how many steps old the sample used is (once per executed step).
    void record_lateness(const Local& l, std::uint64_t k);

    // Steps every local member that can; returns true if any stepped.
    bool advance();

    // Free-running inputs (hardware-in-the-loop): summary lines and <out>/lateness/<member>.yaml.
    void report_lateness();

    int loop();
};

}  // namespace gdnav::runtime
