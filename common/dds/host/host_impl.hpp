#pragma once
// The DDS host's implementation: the parts, each owning its state, wired by Impl, which owns the members, the DDS
// context and the step loop.
//   host_control.hpp     control plane: the control topics (RunControl, Ticks, ComponentStatus, StepDone),
//                        composing host_phase.hpp (phase, timing, the clock's Ticks and silence), host_members.hpp
//                        (member table, dead members) and host_pulse.hpp (heartbeats, the pulse thread)
//   host_inbox.hpp       the inbox of each input (Channel), the outputs, the local members, the in-process hand-over
//   host_inputs.hpp      inputs: inboxes by step, lost and revived inputs, faults on inputs, lateness
//   host_faults.hpp      the fault schedule: live faults, kills, restarts
//   host_observers.hpp   observers: their readers, the mirrors, skipped steps
//   dds_host.cpp         set-up, the main loop, the listener pump
//   host_step.cpp        stepping the members, publishing, StepDone
//   host_configure.cpp   what the member table and live faults change in the parts (matching, rejoin)
#include "dds/compat.hpp"
#include "dds/host/dds_host.hpp"

#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <vector>

#include <fastdds/dds/subscriber/DataReaderListener.hpp>

#include "dds/dds_context.hpp"
#include "dds/host/host_control.hpp"
#include "dds/host/host_faults.hpp"
#include "dds/host/host_inbox.hpp"
#include "dds/host/host_inputs.hpp"
#include "dds/host/host_observers.hpp"

namespace gdnav::dds {

struct DdsHost::Impl final : host::ControlHandler {
    const framework::RunConfig& rc;
    HostOptions opt;
    std::vector<std::unique_ptr<framework::Component>> owned;
    std::vector<host::Local> locals;
    host::ControlPlane control{rc, opt.rejoin};
    host::Inputs inputs{opt.free_running};
    host::Faults faults{opt.rebuild};
    host::Observers observers{rc};
    std::unique_ptr<DdsContext> dds;

    // Data and Tick readers are served from Fast DDS's listener threads (on_data_available): the step's work is
    // done in the thread that received the sample, which saves a thread hand-over per sample. One recursive mutex
    // serialises everything; a write from inside a callback may deliver to a reader of this very process
    // synchronously, so re-entrant calls only fill inboxes (in_advance).
    // Listener threads never block on the mutex (Fast DDS may call them with a reader lock held, and the lock
    // holder may be taking from that reader): they raise `pending` and try_lock; whoever holds the lock drains
    // again before leaving (pump()).
    // Each reader has a listener of its own that first raises its reader's `fresh` flag, so that a pass taken for a
    // sample reads only the readers that received something (a take from an empty reader still costs Fast DDS's
    // bookkeeping per matched writer); the main loop's pass, every kWaitSliceS, reads them all.
    struct ReaderListener final : eprosima::fastdds::dds::DataReaderListener {
        Impl* host{nullptr};
        std::atomic<bool>* fresh{nullptr};
        void on_data_available(eprosima::fastdds::dds::DataReader*) override {
            fresh->store(true);
            host->pump();
        }
    };
    std::deque<ReaderListener> reader_listeners;  // stable addresses; added to by the main loop only
    std::atomic<bool> tick_fresh{true};
    // A new listener for a reader whose samples raise `fresh`.
    eprosima::fastdds::dds::DataReaderListener* listen(std::atomic<bool>* fresh) {
        ReaderListener& l = reader_listeners.emplace_back();
        l.host = this;
        l.fresh = fresh;
        return &l;
    }
    std::recursive_mutex mtx;
    std::atomic<bool> pending{false};
    bool in_advance{false};
    bool not_in_table{false};
    bool closing{false};
    double last_loop_s{0.0};  // when tick_over last ran (own_stall_s)
    // A member's step threw: this process leaves the run with exit code 1 (6 when the exception was a
    // files::WriteError), telling the clock why (STATUS_ERROR) and the launcher too (run_cause.hpp).
    std::string step_error;
    bool step_write_failed{false};

    Impl(const framework::RunConfig& r, std::vector<std::unique_ptr<framework::Component>> m, HostOptions o)
        : rc(r), opt(std::move(o)), owned(std::move(m)) {}

    // DDS goes first: its listeners (ours, the outputs' match counts) must outlive its readers and writers.
    // The pulse thread writes on DDS: it stops before.
    ~Impl() override {
        control.pulse().stop();
        dds.reset();
    }

    void setup();
    // Member c of this process: its inputs' inboxes and readers, its outputs' writers and mirrors.
    host::Local make_local(framework::Component* c);
    // The Tick reader and the inputs' readers made so far (served by the listener).
    std::vector<eprosima::fastdds::dds::DataReader*> data_readers() const;

    // New Tick or data sample (listener threads, and the main loop after its own work).
    void pump();
    // all: every reader (the main loop's pass), else only those whose flag is raised (a listener's pass).
    void process_data(double now, bool all);
    // One pass of the main loop (between waits). Returns false when the run must end; `code` is then the exit code.
    bool tick_over(int& code);
    int loop();
    // The end of the run: the members finish, then the reports.
    int finish(int code);  // kExitOk, or the exit code of the first member whose finish threw

    // ControlHandler: the member table, and a longer fault schedule.
    bool configure(const msg::RunControl& c) override;
    bool live_faults(const msg::RunControl& c) override;
    // After the member table: inputs whose producers are all members of this process lose their DDS reader (they are
    // handed over in the process; host::read_without_dds).
    void drop_local_readers();
    // Member f.target, declared dead, came back (gdnav component --rejoin) and computes again from step
    // f.from_step: this host's inputs from it wait for its samples from that step on; or, if it is ours, it starts
    // there.
    void rejoin(const framework::faults::Fault& f);
    // Whether every reader and writer of the members has matched every peer the member table implies.
    bool all_matched() const;

    // Steps every local member that can; returns true if any stepped.
    bool advance();
    // Member l computes step k (its inputs are bound). An exception from the member sets step_error.
    void step(host::Local& l, std::uint64_t k);
    // A local member's output of step k: into the inboxes of the local readers, and on DDS if anyone outside reads it.
    void publish(host::Output& o, std::uint64_t k);
};

}  // namespace gdnav::dds
